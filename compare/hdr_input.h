// What a comparison means when an input is scene-linear HDR (OpenEXR, Radiance HDR): a lamp at
// 300 with a 1 % error would outweigh every other pixel, and PSNR's peak of 1 means nothing, so
// by default scene-linear input is *developed* to display values first (film/), and thresholds
// keep their units: 1/255 is one 8-bit step of the picture a viewer sees.
//
//   - A scene-linear image compared with a PNG that raintrace developed (its description reads
//     "raintrace develop: …") is developed exactly as that PNG says — exposure, view, look,
//     spikes, softness, bloom, sensor noise, grain, vignetting, for its frame and seed — so the
//     comparison asks "is this PNG its EXR developed?" (the answer is yes within half an 8-bit
//     step of rounding).
//   - Any other scene-linear image is developed with the curve alone: the options' exposure,
//     view and look, without spikes, softness, bloom, noise, grain or vignetting (they would only
//     blur the differences or add noise to them).
//   - linear: the values are compared as stored; PSNR and SSIM, which assume a peak of 1, are
//     not computed, and comparing scene-linear with display values is an error.
#pragma once

#include <memory>
#include <mutex>
#include <string>

#include "compare/image.h"
#include "film/develop.h"

namespace raintrace::compare {

struct HdrOptions {
  /// Compare scene-linear values as stored (`--linear`).
  bool linear = false;
  /// The curve scene-linear input is developed with when its partner names no develop:
  /// exposure_ev, view and look from the options; diffraction spikes, softness, bloom, noise,
  /// grain and vignetting off.
  film::DevelopSettings curve{.bloom = 0.0,
                              .softness = 0.0,
                              .grain = 0.0,
                              .sensor_noise = 0.0,
                              .vignette = 0.0,
                              .aperture_blades = 0};
};

/// Develops scene-linear images for comparison; one per comparison run, shared by its threads
/// (Blender's configuration is loaded once, on first need).
class HdrInput {
 public:
  explicit HdrInput(HdrOptions options);
  ~HdrInput();

  /// Makes `image` comparable with `partner` (the image on the other side; null when missing)
  /// by the rules above. Returns how `image` was developed ("raintrace develop: …"), or ""
  /// when it is compared as stored. Throws std::runtime_error when Blender's configuration is
  /// missing, or when linear values meet display values in linear mode.
  std::string prepare(Image& image, const Image* partner);

 private:
  const film::DisplayTransform& display();

  HdrOptions m_options;
  std::mutex m_mutex;
  std::unique_ptr<film::DisplayTransform> m_display;
};

}  // namespace raintrace::compare
