// The rain beyond the simulated volume as a participating medium (issue 12): the same drops,
// too far to draw one by one, seen as extinction and scattering per metre. Pure.
//
// Each drop removes from a beam twice its cross-section (extinction efficiency Q = 2 for
// drops much larger than the wavelength): once by its geometric shadow (reflected and
// refracted light, sim/drop_optics.h) and once by diffraction, into a cone of about λ/D ≈
// 0.03°. For a picture that diffracted half never leaves the pixel (a 640-pixel, 60° image has
// 0.1° pixels), so it is not lost: the δ-scaling of Joseph, Wiscombe & Weinman (1976) moves it
// back into the beam. What remains is extinction = the geometric cross-section ∫ N·πD²/4 dD
// with the geometric-optics phase function (asymmetry g ≈ 0.77), exactly the light the streaks
// nearer than far_m carry (their coverage sums to the same cross-section), so the medium
// continues the streaks without an edge.
#pragma once

#include "sim/params.h"

namespace raintrace::sim {

struct RainMediumOptics {
  /// ∫ N(D)·πD²/2 dD, 1/m: what a beam loses per metre, diffraction included (Q = 2). About
  /// 1.0e-3 /m at 5 mm/h Marshall-Palmer.
  double extinction_per_m = 0.0;
  /// ∫ N(D)·πD²/4 dD, 1/m: extinction after δ-scaling, what a picture sees. All of it scatters
  /// (water absorbs < 0.1 % over a drop's millimetres).
  double image_extinction_per_m = 0.0;
  /// Henyey-Greenstein asymmetry of the δ-scaled scattering: the geometric-optics g of a water
  /// drop. (g_with_diffraction − ½)/(1 − ½), with g_with_diffraction = (1 + g)/2.
  double eccentricity = 0.0;
};

/// The medium of the configured rain: its drop size distribution, rescaled to carry the
/// configured rate as the simulation's is (DropSizeModel), and a water drop's optics.
RainMediumOptics rain_medium_optics(const RainParams& rain);

}  // namespace raintrace::sim
