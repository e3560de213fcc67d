// Scene-linear light → display picture: Blender's Filmic view through OpenColorIO (OpenImageIO's
// ImageBufAlgo::ociolook and ::ociodisplay), from the configuration Debian ships in blender-data.
//
// Filmic (Troy Sobotka's configuration, as in Blender 2.8–3.x) maps log2 of scene-linear light
// over 16.5 stops, from 0.18 · 2⁻¹⁰ = 0.00018 to 0.18 · 2^6.5 = 16.29, through a film-like
// S-curve to sRGB-encoded display values, desaturating towards white:
//   - 0.00018 and below (scene black) → 1.5e-5: black stays black (< 0.5/255);
//   - middle grey 0.18 → 0.500 with every look (each look keeps grey and changes the contrast);
//   - 1 (diffuse white) → 0.807, 4 → 0.949, 11.5 (6 stops above grey) → 0.994;
//   - 16.29 and above → 1: the only clipping, 6.5 stops above middle grey;
//   - strictly increasing in between.
// "Standard" is plain sRGB encoding clipped at 1 (the look of POV-Ray's own PNGs), for
// comparison with renders made before frames were HDR.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string_view>

#include "film/rgb_image.h"

namespace raintrace::film {

/// Where Debian's package blender-data installs Blender's OpenColorIO configuration.
inline constexpr std::string_view kBlenderOcioConfig =
    "/usr/share/blender/datafiles/colormanagement/config.ocio";

/// The display view: Blender's "Filmic" or "Standard" (sRGB, clipped).
enum class View { filmic, standard };
/// Scene-file names of View, in the order of its values.
inline constexpr std::string_view kViewNames[] = {"filmic", "standard"};

/// Filmic's contrast looks, lowest to highest. medium_contrast is Filmic's own curve (no look
/// applied); the others are Blender's looks of the same name.
enum class Look {
  very_low_contrast,
  low_contrast,
  medium_low_contrast,
  medium_contrast,
  medium_high_contrast,
  high_contrast,
  very_high_contrast,
};
/// Scene-file names of Look, in the order of its values.
inline constexpr std::string_view kLookNames[] = {
    "very-low-contrast",    "low-contrast",  "medium-low-contrast", "medium-contrast",
    "medium-high-contrast", "high-contrast", "very-high-contrast"};

std::string_view to_string(View view);  ///< "filmic", "standard" (scene-file spelling)
std::string_view to_string(Look look);  ///< "very-low-contrast" … "very-high-contrast"
std::optional<View> parse_view(std::string_view text);  ///< exact scene-file spelling only
std::optional<Look> parse_look(std::string_view text);  ///< exact scene-file spelling only

/// One loaded configuration with its nine transforms (two views, six looks besides Filmic's own
/// curve) built once; load it once per run and share it. to_display() may be called from several
/// threads at once.
class DisplayTransform {
 public:
  /// Loads the OpenColorIO configuration at `config`. Throws std::runtime_error with one line
  /// when the file is missing ("… install the Debian package blender-data") or when it lacks
  /// the display "sRGB", its views "Filmic" and "Standard", or one of the seven looks.
  explicit DisplayTransform(const std::filesystem::path& config = kBlenderOcioConfig);
  ~DisplayTransform();
  DisplayTransform(const DisplayTransform&) = delete;
  DisplayTransform& operator=(const DisplayTransform&) = delete;

  /// Scene-linear Rec. 709 values (the configuration's "Linear"; >= 0) → display-encoded sRGB
  /// in [0, 1], per pixel, on the calling thread, and deterministic (the same input gives the
  /// same output bits whatever OpenImageIO's thread setting). `look` applies to the Filmic view
  /// only; View::standard ignores it. Throws std::runtime_error if OpenColorIO fails.
  RgbImage to_display(const RgbImage& linear, View view, Look look) const;

  /// to_display() of a fixed set of inputs (every combination of 12 levels from 0 to 100 in
  /// R, G and B: greys, colours, black and far beyond white). Whoever records what a picture
  /// was developed with hashes this: another blender-data or OpenColorIO that would change the
  /// pixels changes it too, without hashing 23 MB of LUT files.
  RgbImage response(View view, Look look) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace raintrace::film
