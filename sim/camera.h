// The camera as the simulation sees it: a view frustum that drops are spawned into and culled
// against. Pure geometry; POV-Ray's camera statement is povgen's business.
#pragma once

#include <glm/vec3.hpp>

namespace raintrace::sim {

struct Camera {
  /// Eye position, metres. Default (0, 1.6, -5): eye height, 5 m in front of the origin.
  glm::dvec3 position{0.0, 1.6, -5.0};
  /// Point looked at, metres; must differ from position. Default (0, 1.6, 0).
  glm::dvec3 look_at{0.0, 1.6, 0.0};
  /// Horizontal field of view, degrees, in (1, 170). Default 60.
  double fov_deg = 60.0;
  /// Width / height of the image, > 0. Set from [output] width and height. Default 16/9.
  double aspect = 16.0 / 9.0;
  /// Image width in pixels, >= 1. Set from [output] width: the ground's level of detail (how
  /// many impacts are worth simulating at a distance) follows the size of a pixel. Default 640.
  int width_px = 640;
  /// Exposure (the paper's persistence time t in eq. 3), seconds, in [0, 1]. Default 0.02.
  double exposure_s = 0.02;
};

}  // namespace raintrace::sim
