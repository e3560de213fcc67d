// A digital camera's noise, added to the exposed scene-linear frame before the film's response:
// photon shot noise, whose variance grows with the light, over a floor of read noise. Unlike
// film grain (grain.h), which is strongest in the mid-tones of the developed picture, it is
// strongest *relative to the signal* in the shadows, and each colour channel starts with its own
// (the camera then smooths that colour speckle into faint blotches, below). Blind viewers of the
// default street, given grain alone: "real sensor noise at night is much heavier in the shadows and
// gets blotchy colour there; this reads as a render with a grain filter".
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
// noise into its neighbours) and drawn independently for R, G and B, as each colour's photosites
// collect their own light. Then, as every camera's processing does, the colour part of the noise
// (each channel's departure from the three channels' mean) is smoothed by a Gaussian of
// kChromaSmoothingPx, while the luminance part (that mean, σ/√3 in each channel) stays as fine
// as the photosites drew it. The independent colour speckle of the raw photosites read to blind
// viewers as "an even, colourful speckle that looks like leftover render noise" and "a pattern
// no real sensor produces"; with the colour smoothed both chose it over the raw speckle, "fine,
// mostly brightness noise with little colour speckle … like a high-ISO cinema camera after light
// noise reduction" (BENCHMARKS.md, "The sensor's colour noise smoothed as cameras do").
#pragma once

#include <cstdint>

#include "film/rgb_image.h"

namespace raintrace::film {

/// The strongest noise accepted: 0.5 is already a picture made of speckle.
inline constexpr double kMaxSensorNoise = 0.5;
/// How far a camera's processing smooths the colour part of the noise: a Gaussian's standard
/// deviation in pixels of a 1920-pixel-wide frame (less at smaller sizes, as the photosites'
/// noise is). Chosen blind at 1280 pixels, where it was two passes of a 7-pixel box (σ = 2.8 px
/// there, 4.2 at 1920); 4 because the smoothing is the lens's softness blur, whose widest is 4.
inline constexpr double kChromaSmoothingPx = 4.0;
/// Read noise in electrons: current large CMOS sensors read 1.5–3 e⁻ at high ISO
/// (input-referred). It matches the shot noise where N = 9 electrons: at s = 0.05, 5.5 stops
/// below mid-grey (L = 0.004); above that the shot noise rules.
inline constexpr double kReadNoiseElectrons = 3.0;

/// σ(L) above, for an exposed scene-linear value `linear` (negative counts as 0: no light) of a
/// frame `width` pixels wide. 0 when strength is 0.
double sensor_noise_rms(double strength, int width, double linear);

/// Adds the noise to an exposed scene-linear image: out = max(0, L + σ(L) · n_c(x, y)) per
/// channel c, where n_c = m + G ∗ (u_c − m): u_c = clumped_noise with a seed of its own for each
/// channel, m their mean (variance 1/3), G the Gaussian of kChromaSmoothingPx. The same seed and
/// frame give the same noise on any machine and thread count. strength in [0, kMaxSensorNoise]
/// (throws std::invalid_argument otherwise; 0 leaves the image unchanged). The noise has mean
/// 0; the clamp at 0 (no negative light reaches the display transform) lifts the mean of a
/// black pixel by the channel's RMS over √(2π): σ(0)/√(2π) at most, 5·10⁻⁴ at s = 0.05 (Filmic
/// shows it as 0.3/255), about 0.6 of that where the colour part is smoothed to blotches.
void apply_sensor_noise(RgbImage& image, double strength, std::uint64_t seed, std::int64_t frame);

}  // namespace raintrace::film
