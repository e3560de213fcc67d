// The difference picture: |A − B| as a heat map, amplified so small errors show, with a colour
// scale bar and its numbers underneath so the picture can be read without the report.
#pragma once

#include "compare/image.h"

namespace raintrace::compare {

/// Per pixel the largest |a − b| over all channels (alpha included; a non-finite mismatch counts
/// as full scale) mapped through black → red → yellow → white, with full_scale at white. Returns
/// an RGB image a.width wide and a.height + scale_bar_height(a.width) high: the heat map on top,
/// below it the colour ramp from 0 to full_scale labelled "0", full_scale/2 and full_scale.
/// full_scale <= 0 picks it automatically: the largest error rounded up to 1, 2 or 5 × 10^k,
/// at least 1/255 (one 8-bit step) so identical images give a black map, not noise blown up.
/// a and b must have equal sizes (std::invalid_argument otherwise).
Image difference_heatmap(const Image& a, const Image& b, double full_scale = 0.0);

/// The full scale difference_heatmap picks for a largest error of max_error (see above).
double auto_full_scale(double max_error);

/// Height in pixels of the scale bar under a heat map of this width: 16 · max(1, width / 320).
int scale_bar_height(int width);

/// The heat map colour of t in [0, 1] (clamped): RGB written to rgb[0..2].
void heat_colour(double t, float rgb[3]);

}  // namespace raintrace::compare
