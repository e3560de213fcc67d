// The three resampling steps bloom builds its wide point-spread function from. Each one
// conserves energy by construction (the sum of every channel, counted in full-resolution pixel
// areas, is unchanged up to float rounding) at any image size, odd sizes and edges included, so
// bloom conserves energy because its parts do. Values are means over a pixel's area.
#pragma once

#include "film/rgb_image.h"

namespace raintrace::film {

/// Half resolution: ceil(w/2) × ceil(h/2), each pixel the mean of the 2×2 block it covers. An
/// odd last row or column is padded with black, so its block holds the same light in a cell
/// twice as large: 4 · sum(out) = sum(in) exactly (up to rounding).
RgbImage downsample_half(const RgbImage& in);

/// Back to `width` × `height`, which must be 2·in.width or 2·in.width − 1 (and likewise for the
/// height): bilinear interpolation between pixel centres, edges clamped (the first and last half
/// pixel repeat the edge value). With an odd target the padding row or column that
/// downsample_half added is folded back onto the last real one, so sum(out) = 4 · sum(in).
/// Throws std::invalid_argument for any other size.
RgbImage upsample_double(const RgbImage& in, int width, int height);

/// Separable binomial blur [1 4 6 4 1] / 16 (variance 1 pixel² along each axis) with the image
/// mirrored at its edges (… 1 0 | 0 1 2 …): light that would leave the frame is reflected back,
/// so sum(out) = sum(in) for any size, 1×1 included.
RgbImage blur_binomial5(const RgbImage& in);

/// sum += weight · blur_binomial5(in), without a full-size temporary (sum must be in's size;
/// throws std::invalid_argument otherwise). Bloom adds each level's blur into its running sum.
void add_blurred(RgbImage& sum, const RgbImage& in, float weight);

}  // namespace raintrace::film
