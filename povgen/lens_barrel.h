// The lens barrel's rim in front of the opening, for [camera] optical_vignetting: the stop that
// clips the out-of-focus discs toward the frame's corners into cat's eyes, as a real lens
// wide open does, and darkens the corners with them.
//
// POV-Ray's focal blur starts each ray of a pixel at a point of the opening (a disc across the
// view direction at the camera) and aims it at the pixel's point of focus. A thin ring in front
// of the opening, at distance L along the view direction with a hole of radius H, stops the rays
// that pass outside the hole. At L the rays of a pixel whose chief ray leaves the axis at
// tan θ = t fill a disc of radius ρ·(1 − L/F) around L·t (ρ the opening's radius, F the focus
// distance). The ring is placed so that
//   - the discs of pixels out to (1 − s) of the way from the centre to a corner just fit the
//     hole: ρ·(1 − L/F) + L·(1 − s)·τ = H (τ = tan of the half-diagonal field);
//   - the corner's chief ray meets the rim: H = L·τ, so the corner keeps half of its opening;
// s being optical_vignetting. Then L = ρ / (s·τ + ρ/F).
#pragma once

#include <string>

#include "povgen/export_params.h"

namespace raintrace::povgen {

/// Where the rim stands: its distance in front of the opening along the view direction, and
/// the radius of its hole, both in m.
struct LensBarrel {
  double distance_m = 0.0;
  double hole_radius_m = 0.0;
};

/// The rim for look (look.optical_vignetting > 0 with a traced focal blur).
LensBarrel lens_barrel(const ExportParams& look);

/// tan of the angle between the view direction and a corner of the frame.
double half_diagonal_tan(const ExportParams& look);

/// The rim as POV-Ray text (a black disc with a hole, seen by camera rays only), or nothing
/// when look.optical_vignetting is 0.
std::string lens_barrel_text(const ExportParams& look);

}  // namespace raintrace::povgen
