// Glare and bloom: the light a lens scatters around bright sources, spread in scene-linear light
// before the display transform, so a street lamp at 50× white gets a halo and a faint veil over
// the frame while the total light in the picture stays what the scene sent.
//
// out = (1 − k) · in + k · (in ⊛ PSF), k = `strength`, with a normalised point-spread function
// that falls off as 1/r² — the r⁻² law of disability glare (Stiles–Holladay; the θ⁻² term of
// CIE 146:2002's glare spread function), i.e. the same energy in every octave of radius — from
// about a pixel at 1280 px wide out to a ninth of the frame width. It is built as a sum of
// Gaussians with equal weights, one per pyramid level l:
//
//     PSF(r) = Σ_l w_l · exp(−r² / (2 σ_l²)) / (2π σ_l²),   σ_l² = 4^l + (4^l − 1) · 11/36 px²,
//
// (the binomial blur at level l, plus the box downsamples and bilinear upsamples that carry it
// there and back: σ_0 = 1 px, σ_1 = 2.2 px, σ_7 = 146 px). The levels are chosen from the image
// width so the glare covers the same part of the frame at every resolution (within half an
// octave); levels finer than one pixel (below about 900 px wide) keep their share unscattered.
#pragma once

#include <vector>

#include "film/rgb_image.h"

namespace raintrace::film {

/// One Gaussian of the point-spread function.
struct BloomLevel {
  int level = 0;        ///< pyramid level >= 0: the blur runs at 2^level × coarser resolution
  double sigma_px = 0;  ///< its standard deviation in full-resolution pixels (formula above)
  double weight = 0;    ///< its share of the scattered light; the weights of all levels sum to
                        ///< 1 minus the share of levels below one pixel at this width
};

/// The levels of the point-spread function for an image `width` pixels wide (>= 1): nominally
/// the eight levels o … o + 7 with o = round(log2(width / 1280)), each weighing 1/8; levels
/// below 0 are left out (their weight is not redistributed: that light stays in its pixel).
std::vector<BloomLevel> bloom_levels(int width);

/// Applies out = (1 − k)·in + k·(in ⊛ PSF) with k = strength in [0, 1] (throws
/// std::invalid_argument otherwise); strength 0 returns the input unchanged. Input values must
/// be finite. Energy: the sum of each channel is unchanged up to float rounding (every step is
/// conservative: see pyramid.h). Edges mirror the image, so light scattered past the frame
/// edge is reflected back in instead of lost.
RgbImage bloom(const RgbImage& in, double strength);

}  // namespace raintrace::film
