// Film grain on the developed (display-encoded) picture. Grain is strongest in the mid-tones and
// vanishes in clear shadows and full highlights: in the Boolean model of a developed emulsion
// (Newson, Delon & Galerne, "A Stochastic Film Grain Model for Resolution-Independent
// Rendering", Computer Graphics Forum 2017) a patch of mean grey v is covered by grains with
// probability v, so its fluctuation has variance ∝ v(1 − v). Following Selwyn's law (RMS
// granularity × √area = constant), a pixel that covers more of the frame averages more grains:
// the RMS per pixel scales with the image width, so previews and finals look alike at the same
// viewed size.
#pragma once

#include <cstdint>

#include "film/rgb_image.h"

namespace raintrace::film {

/// The strongest grain accepted (RMS 0.5 on mid-grey already swamps the picture).
inline constexpr double kMaxGrain = 0.5;

/// Per-pixel RMS of the grain at display value v for a frame `width` pixels wide:
/// strength · (width / 1920) · 2·√(v(1 − v)), i.e. `strength` is the RMS on mid-grey (v = 0.5)
/// of a 1920-pixel-wide frame, and 0 at v = 0 and v = 1. v outside [0, 1] counts as the bound.
double grain_rms(double strength, int width, double v);

/// Adds grain to a display-encoded image (values in [0, 1]), strength in [0, 0.5] (throws
/// std::invalid_argument otherwise; 0 leaves the image unchanged):
///   out = clamp(v + grain_rms(strength, width, v) · n(x, y), 0, 1)
/// per channel, where n is one noise value per pixel shared by R, G and B (luminance grain:
/// per-channel noise reads as a digital sensor's chroma noise). n has mean 0 and variance 1, and
/// neighbouring pixels share part of it (correlation 0.44 across a side, 0.06 two pixels apart):
/// a developed emulsion's grains clump to about a pixel of a 1280–1920-pixel frame, and noise
/// independent from pixel to pixel reads as a renderer's sampling noise (a blind viewer: "looks
/// like leftover path-tracer noise"). Each pixel's hash of (x, y, frame, seed) gives four uniform
/// numbers, summed, centred and scaled (Irwin–Hall); n is those of the pixel and its eight
/// neighbours weighted (1, 4, 1) ⊗ (1, 4, 1) over their root sum of squares (|n| < 6.93). It is
/// a pure function of (x, y, frame, seed), so the same seed and frame give byte-identical grain
/// on any machine and thread count, and consecutive frames differ. Before the clamp the grain's
/// expectation is 0, so it does not shift the mean brightness.
void apply_grain(RgbImage& image, double strength, std::uint64_t seed, std::int64_t frame);

}  // namespace raintrace::film
