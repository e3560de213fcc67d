// Checks of SimParams and Camera built in code: every scene-file field against its table row
// (params.h, camera.h), plus the few rules that are not a range.
#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <string>

#include "sim/camera.h"
#include "sim/params.h"

namespace raintrace::sim {

bool has_view_direction(const Camera& camera) {
  return glm::length(camera.look_at - camera.position) >= 1e-6;
}

bool looks_straight_up_or_down(const Camera& camera) {
  const glm::dvec3 view = camera.look_at - camera.position;
  return std::hypot(view.x, view.z) < 1e-6 * glm::length(view);
}

bool is_horizontal_direction(const glm::dvec3& direction) {
  return std::hypot(direction.x, direction.z) >= 1e-9;
}

void validate(const Camera& camera) {
  check_params<Camera>(kCameraParams, camera);
  if (!has_view_direction(camera)) {
    throw std::invalid_argument("camera.look_at must differ from camera.position");
  }
  if (looks_straight_up_or_down(camera)) {
    throw std::invalid_argument(
        "camera.look_at must not lie straight above or below camera.position");
  }
  if (!(camera.aspect > 0.0 && std::isfinite(camera.aspect))) {
    throw std::invalid_argument("camera.aspect must be > 0 (got " + number_text(camera.aspect) +
                                ")");
  }
  if (camera.width_px < 1) {
    throw std::invalid_argument("camera.width_px must be >= 1 (got " +
                                std::to_string(camera.width_px) + ")");
  }
}

void validate(const SimParams& p) {
  validate(p.camera);
  check_params<RainParams>(kRainParams, p.rain);
  check_params<WindParams>(kWindParams, p.wind);
  if (!is_horizontal_direction(p.wind.gust_direction)) {
    throw std::invalid_argument("wind.gust_direction must point somewhere horizontally");
  }
  check_params<SplashParams>(kSplashParams, p.splashes);
  check_params<PuddleParams>(kPuddleParams, p.puddles);
  check_params<RippleParams>(kRippleParams, p.ripples);
  check_params<LightningParams>(kLightningParams, p.lightning);
  check_params<SimParams>(kSimParams, p);
  if (p.threads < 0 || p.threads > 1024) {
    throw std::invalid_argument("threads must be in [0, 1024] (got " + std::to_string(p.threads) +
                                ")");
  }
}

}  // namespace raintrace::sim
