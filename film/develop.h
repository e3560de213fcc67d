// Developing a frame: the rendered scene-linear HDR frame → the picture a camera would show.
// The order follows the light: the camera's white balance and exposure, the lens (vignetting,
// the iris's diffraction spikes, its softness, then glare scattered inside it), the sensor's
// noise, the film's response (Filmic via OpenColorIO), then grain in the developed picture.
//
//   linear ─white balance─▶ ─exposure_ev─▶ ─vignette (cos⁴)─▶ ─diffraction spikes─▶ ─softness─▶
//   ─bloom (energy-conserving)─▶ ─sensor noise─▶ ─view + look─▶ ─grain─▶ display sRGB ─8-bit─▶ PNG
//
// Usage:
//   const film::DisplayTransform filmic;                   // once: loads Blender's config
//   film::develop_file("images/frame_0016.exr", "images/frame_0016.png",
//                      film::DevelopSettings{.exposure_ev = -1}, {.fov_deg = 60, .seed = 1,
//                      .frame = 16}, filmic);
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "film/display_transform.h"
#include "film/rgb_image.h"

namespace raintrace::film {

/// How the camera develops every frame of a clip (the scene file's `[camera]` look keys).
struct DevelopSettings {
  /// Exposure in stops, [−16, 16]; 0 = scene values as rendered (0.18 → display 0.5). Default 0.
  double exposure_ev = 0.0;
  /// The colour temperature (K) the camera is balanced for, [2000, 20000], or 0 (see
  /// white_balance.h): light of that temperature develops as grey. Default 0: D65 is white, the
  /// frame's colours as traced.
  double white_balance_k = 0.0;
  /// Display view. Default filmic.
  View view = View::filmic;
  /// Filmic contrast look (filmic view only; the standard view ignores it). Default
  /// medium_high_contrast: deeper shadows than Filmic's base curve, which suits a night scene's
  /// mostly dark frame.
  Look look = Look::medium_high_contrast;
  /// Share of the light the lens scatters into glare, [0, 1] (see bloom.h). Default 0.04, in the
  /// range of measured veiling glare of photographic lenses (ISO 9358's veiling glare index is
  /// a few per cent): a soft halo around lamps far brighter than white, invisible elsewhere.
  double bloom = 0.04;
  /// The lens's own blur: a Gaussian's standard deviation in pixels of a 1920-pixel-wide frame,
  /// [0, 4] (see softness.h). Default 0 (every pixel as traced).
  double softness = 0.0;
  /// Grain RMS on mid-grey of a 1920-pixel-wide frame, [0, 0.5] (see grain.h). Default 0.02
  /// (5/255 on mid-grey at 1920 px, 1.7/255 at 640 px): fine, like a fast film stock scanned,
  /// enough to take the computer-clean edge off flat areas. 0 turns it off.
  double grain = 0.02;
  /// A digital sensor's shot and read noise: its relative RMS at scene-linear mid-grey on a
  /// 1920-pixel-wide frame, [0, 0.5] (see sensor_noise.h). Default 0 (off): grain alone.
  double sensor_noise = 0.0;
  /// Strength of the cos⁴ falloff, [0, 1] (see vignette.h). Default 0.5: corners 0.43 stops
  /// darker at 60° and 16:9, a gentle darkening that holds the eye in the frame. 0 turns it off.
  double vignette = 0.5;
  /// How many straight blades form the lens's iris, 0 or [3, kMaxApertureBlades] (see
  /// diffraction_spikes.h): bright lights get a star of diffraction spikes, N rays for N even,
  /// 2N for N odd. Default 0: a round opening, no spikes. Needs FrameContext::aperture_m > 0.
  int aperture_blades = 0;
};

/// What develop needs to know about the frame itself.
struct FrameContext {
  double fov_deg = 60.0;   ///< the camera's horizontal field of view, (0, 180), for vignetting
  std::uint64_t seed = 1;  ///< the scene's seed, for grain
  std::int64_t frame = 1;  ///< the frame number, for grain
  /// The lens opening's diameter (m; the scene's [camera] aperture_m), for the diffraction
  /// spikes: > 0 whenever aperture_blades is not 0.
  double aperture_m = 0.0;
};

/// Throws std::invalid_argument naming the field when a setting is out of its range.
void validate(const DevelopSettings& settings);

/// One line recording the settings, e.g. "raintrace develop: exposure_ev=-1 view=filmic
/// look=medium-high-contrast bloom=0.04 grain=0 vignette=0" (no look with the standard view;
/// "white_balance_k=…" after exposure_ev, "softness=…" after bloom, "sensor_noise=…" after grain
/// and "aperture_blades=…" last only when they are not 0, so pictures developed before they
/// existed keep their description).
/// Numbers in their shortest exact form, so parse_description() gives the same settings back.
std::string describe(const DevelopSettings& settings);
/// The same followed by the frame: "… fov_deg=60 seed=1 frame=16", with " aperture_m=…" after
/// fov_deg when aperture_blades is not 0. develop_file() writes this into each PNG, so a PNG says
/// exactly how to develop its EXR again.
std::string describe(const DevelopSettings& settings, const FrameContext& frame);

/// What a PNG's description says it was developed with.
struct DevelopDescription {
  DevelopSettings settings;
  FrameContext frame;
};
/// Reads describe(settings, frame) back; nullopt for any other text (a PNG raintrace did not
/// develop), a missing field (white_balance_k, softness, sensor_noise and aperture_blades may be
/// missing: 0;
/// aperture_m must be there when aperture_blades is not 0), or a value out of range.
std::optional<DevelopDescription> parse_description(std::string_view text);

/// Scene-linear frame → display-encoded sRGB in [0, 1], each step as its header says.
/// Deterministic: the same input, settings and context give the same bits on any thread count.
RgbImage develop(const RgbImage& linear, const DevelopSettings& settings, const FrameContext& frame,
                 const DisplayTransform& display);

/// Reads an HDR frame (read_rgb_image), develops it and writes an 8-bit sRGB PNG (write_png,
/// atomically, with describe(settings, frame) as its description). The input file is not touched.
/// Throws std::runtime_error naming the file on I/O errors, std::invalid_argument for settings.
void develop_file(const std::filesystem::path& hdr_in, const std::filesystem::path& png_out,
                  const DevelopSettings& settings, const FrameContext& frame,
                  const DisplayTransform& display);

}  // namespace raintrace::film
