// A digital camera's noise, added to the exposed scene-linear frame before the film's response:
// photon shot noise, whose variance grows with the light, over a floor of read noise. Unlike
// film grain (grain.h), which is strongest in the mid-tones of the developed picture, it is
// strongest *relative to the signal* in the shadows, and each colour channel has its own (the
// colour speckle of a night exposure at high ISO). Blind viewers of the default street, given
// grain alone: "real sensor noise at night is much heavier in the shadows and gets blotchy
// colour there; this reads as a render with a grain filter".
//
// Model: a pixel whose exposed value is L collects N = L / (0.18 · s²) photoelectrons, s being
// the relative RMS at mid-grey (L = 0.18, where N = 1/s²); shot noise is √N electrons, read noise
// kReadNoiseElectrons, so in units of L
//
//     σ(L) = √(0.18 · s² · L + (0.18 · s² · n_read)²),   s = strength · width / 1920.
//
// `strength` is the relative RMS at mid-grey of a 1920-pixel-wide frame; a smaller frame's pixel
// gathers the light of more photosites, so its relative noise is smaller in proportion to the
// width (the same law as grain's Selwyn scaling: the picture looks alike at the same viewed
// size). Noise is clumped over about a pixel (pixel_noise.h: demosaicing spreads a photosite's
// noise into its neighbours) and independent between R, G and B.
#pragma once

#include <cstdint>

#include "film/rgb_image.h"

namespace raintrace::film {

/// The strongest noise accepted: 0.5 is already a picture made of speckle.
inline constexpr double kMaxSensorNoise = 0.5;
/// Read noise in electrons: current large CMOS sensors read 1.5–3 e⁻ at high ISO
/// (input-referred). It matches the shot noise where N = 9 electrons: at s = 0.05, 5.5 stops
/// below mid-grey (L = 0.004); above that the shot noise rules.
inline constexpr double kReadNoiseElectrons = 3.0;

/// σ(L) above, for an exposed scene-linear value `linear` (negative counts as 0: no light) of a
/// frame `width` pixels wide. 0 when strength is 0.
double sensor_noise_rms(double strength, int width, double linear);

/// Adds the noise to an exposed scene-linear image: out = max(0, L + σ(L) · n_c(x, y)) per
/// channel c, n_c = clumped_noise with a seed of its own for each channel, so the same seed and
/// frame give the same noise on any machine and thread count. strength in [0, kMaxSensorNoise]
/// (throws std::invalid_argument otherwise; 0 leaves the image unchanged). The noise has mean
/// 0; the clamp at 0 (no negative light reaches the display transform) lifts the mean of a
/// black pixel by σ(0)/√(2π), 5·10⁻⁴ at s = 0.05 (Filmic shows it as 0.3/255).
void apply_sensor_noise(RgbImage& image, double strength, std::uint64_t seed, std::int64_t frame);

}  // namespace raintrace::film
