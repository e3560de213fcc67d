// The star a lens draws around a bright light: diffraction at the straight edges of its iris.
// Light passing an aperture is spread by diffraction; far from the image of a point, the share
// of its light landing beyond an angle θ is
//
//     E(>θ) = λ·P / (2π²·A·θ)       (P the opening's perimeter, A its area; θ ≫ λ/D),
//
// the edge-diffraction tail of any aperture (for a circle, P/A = 4/D gives the Airy pattern's
// 2λ/(π²Dθ)). A round opening spreads that light evenly around the point, too faintly to see.
// An iris of N straight blades is a polygon: each edge throws its share into a thin line at right
// angles to it, so the same light piles into N lines through the point (N even: parallel edges
// share one) or 2N (N odd) — the star of a street lamp in a night photograph. Its rays grow
// fainter as 1/r², and longer for red light than for blue (E ∝ λ).
//
// The spikes are sub-pixel thin (λ over an edge's length), so each ray is drawn one pixel wide,
// sampled every pixel along it. Only pixels far above white spread light: a pixel at 1 (scene-
// linear, after exposure) sends under 0.006 into its nearest neighbour, too little to see next
// to it, and a ray stops where its samples fall below 1e-4, under Filmic's black. What a pixel
// sends is taken from it, so light is conserved but for rays running off the frame.
#pragma once

#include "film/rgb_image.h"

namespace raintrace::film {

/// The most blades accepted (0 = a round opening: no spikes).
inline constexpr int kMaxApertureBlades = 16;
/// Whether an iris can have `blades` blades: 0 (round) or a polygon of 3 to kMaxApertureBlades.
inline constexpr bool is_blade_count(int blades) {
  return blades == 0 || (blades >= 3 && blades <= kMaxApertureBlades);
}

/// A lens's opening for diffraction: how many straight blades form it (0, or 3 … 16) and its
/// diameter (m, that of the circle through the polygon's corners).
struct Aperture {
  int blades = 0;
  double diameter_m = 0.0;
};

/// The share of a point's light, in each of R, G and B, that lands farther than one pixel from
/// it in a frame `width` pixels wide with horizontal field of view `fov_deg` — E(>θ) above at
/// θ = one pixel — for wavelengths 610, 550 and 465 nm. 0 for a round opening.
struct SpikeShare {
  double rgb[3] = {0.0, 0.0, 0.0};
};
SpikeShare spike_share_beyond_one_pixel(const Aperture& aperture, double fov_deg, int width);

/// How many rays the star has: N for N even, 2N for N odd, 0 for a round opening.
int spike_rays(int blades);

/// Draws the spikes into the scene-linear image (after exposure): every pixel with a channel of
/// at least 1 sends, into each of spike_rays() rays at right angles to the blades' edges (one
/// edge at the bottom, horizontal: for 6 blades, rays up, down and at ±30° from horizontal),
/// per ray at r = 1, 2, … pixels its share E(>r − ½) − E(>r + ½), until a sample falls under
/// 1e-4. Throws std::invalid_argument for blades outside {0, 3 … 16}, a diameter not > 0 with
/// blades, or fov_deg outside (0, 180). blades = 0 leaves the image unchanged. Deterministic.
void apply_diffraction_spikes(RgbImage& image, const Aperture& aperture, double fov_deg);

}  // namespace raintrace::film
