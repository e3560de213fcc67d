// Vignetting: the natural cos⁴ falloff of a lens. Light reaching the sensor at an angle θ off
// the axis is dimmed by cos⁴θ (the inverse square of the longer path, the tilted aperture and
// the tilted sensor area); real lenses add mechanical vignetting and are partly corrected, so a
// strength blends between no falloff and the full cos⁴ law. Applied in scene-linear light.
#pragma once

#include "film/rgb_image.h"

namespace raintrace::film {

/// Multiplies each pixel by (1 − s) + s · cos⁴θ, s = strength in [0, 1], where θ is the angle
/// between the optical axis and the ray through the pixel's centre (x + ½, y + ½) of a pinhole
/// camera with horizontal field of view `fov_deg` in (0, 180): tan θ = r / f, r the distance in
/// pixels from the image centre and f = (width / 2) / tan(fov / 2). The centre is unchanged;
/// at 60° and 16:9 the corners get cos⁴θ = 0.48 (−1.06 stops) at strength 1. Throws
/// std::invalid_argument for a strength or field of view out of range.
void apply_vignette(RgbImage& image, double strength, double fov_deg);

}  // namespace raintrace::film
