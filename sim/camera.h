// The camera as the simulation sees it: a view frustum that drops are spawned into and culled
// against. Pure geometry; POV-Ray's camera statement is povgen's business.
#pragma once

#include <glm/vec3.hpp>

#include "sim/param_table.h"

namespace raintrace::sim {

/// Units and valid ranges of the fields are in kCameraParams below; defaults are the
/// member initialisers.
struct Camera {
  /// Eye position: eye height, 5 m in front of the origin.
  glm::dvec3 position{0.0, 1.6, -5.0};
  /// Point looked at; must differ from position.
  glm::dvec3 look_at{0.0, 1.6, 0.0};
  /// Horizontal field of view. Below 1° the frustum holds almost no rain; beyond 170°
  /// POV-Ray's perspective camera stretches the edges past use.
  double fov_deg = 60.0;
  /// Width / height of the image, > 0; set from [output] width and height.
  double aspect = 16.0 / 9.0;
  /// Image width in pixels, >= 1; set from [output] width: the ground's level of detail (how
  /// many impacts are worth simulating at a distance) follows the size of a pixel.
  int width_px = 640;
  /// Exposure, s: the paper's persistence time t in eq. 3.
  double exposure_s = 0.02;
};

/// Positions anywhere, metres from the origin: beyond 100 km single-precision drop
/// coordinates in a frame and POV-Ray's own precision stop resolving millimetre drops.
inline constexpr Range kCoordinates = Range::closed(-1e5, 1e5);

/// [camera]: the scene-file keys of Camera (aspect comes from [output] width and height).
inline constexpr Param<Camera> kCameraParams[] = {
    vector("camera", "position", &Camera::position, "m", kCoordinates),
    vector("camera", "look_at", &Camera::look_at, "m", kCoordinates)
        .with_note("≠ `position`, not straight above or below it"),
    number("camera", "fov_deg", &Camera::fov_deg, "degrees", Range::open(1.0, 170.0)),
    number("camera", "exposure_s", &Camera::exposure_s, "s", Range::closed(0.0, 1.0)),
};
static_assert(well_formed<Camera>(kCameraParams));

/// Where the camera looks from position to look_at: false when the two (nearly) coincide.
bool has_view_direction(const Camera& camera);
/// True when look_at lies straight above or below position, where a camera that keeps +y up
/// has no right vector.
bool looks_straight_up_or_down(const Camera& camera);

/// Throws std::invalid_argument naming the first field of the camera that is out of its
/// range (kCameraParams), a position equal to look_at or a non-positive aspect.
void validate(const Camera& camera);

}  // namespace raintrace::sim
