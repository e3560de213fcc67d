// The lens's own softness: no real lens and sensor draw an edge within one pixel. Aberrations,
// diffraction at the stop, the sensor's anti-aliasing filter and demosaicing spread each point
// of light over a pixel or so, so the brightest edges — a lit sign's letters, a strip light, a
// glint on rippled water — fade over a pixel into their surroundings. A ray tracer's pixel edge
// does not: a strip light at twelve times white stays white to its last, antialiased pixel, and
// blind viewers read those edges as "aliased, stair-stepped". Applied in scene-linear light
// before glare, so a highlight spreads as the light it is, not as the display's clipped white.
#pragma once

#include "film/rgb_image.h"

namespace raintrace::film {

/// The softest lens accepted, in pixels of a 1920-pixel-wide frame.
inline constexpr double kMaxSoftness = 4.0;

/// The blur's standard deviation in pixels of a frame `width` pixels wide: `softness` is the
/// one of a 1920-pixel-wide frame, so the blur covers the same share of the frame at any size
/// (a 640-pixel preview gets a third of it).
double softness_sigma_px(double softness, int width);

/// Blurs the image with a separable Gaussian of standard deviation σ = softness_sigma_px(softness,
/// image.width) pixels: the Gaussian sampled at whole pixel offsets out to ⌈3σ⌉ (at least 1) and
/// normalised, the image mirrored at its edges (… 1 0 | 0 1 2 …) so that light that would leave
/// the frame is reflected back: the sum of each channel is unchanged (up to float rounding).
/// softness in [0, kMaxSoftness] (throws std::invalid_argument otherwise); 0, or a σ under 0.05
/// px, leaves the image unchanged.
void apply_softness(RgbImage& image, double softness);

}  // namespace raintrace::film
