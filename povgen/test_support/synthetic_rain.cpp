// Synthetic rain (see synthetic_rain.h).
#include "povgen/test_support/synthetic_rain.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "sim/random.h"
#include "sim/terminal_velocity.h"

namespace raintrace::povgen::test_support {
namespace {

/// Uniform in [0, 1): dimension k of drop id, from sim's counter-based hash.
double uniform(std::uint64_t seed, std::uint64_t id, std::uint64_t k) {
  return sim::to_unit(sim::mix64(seed ^ sim::mix64(id * 8 + k)));
}

}  // namespace

sim::Frame synthetic_rain(std::size_t count, const sim::Camera& camera, double aspect, double far_m,
                          double wind_x_m_per_s, std::uint64_t seed) {
  sim::Frame frame;
  frame.index = 1;
  const glm::dvec3 forward = glm::normalize(camera.look_at - camera.position);
  const glm::dvec3 right = glm::normalize(glm::cross(glm::dvec3{0, 1, 0}, forward));
  const glm::dvec3 up = glm::cross(forward, right);
  const double tx = std::tan(camera.fov_deg * std::numbers::pi / 360.0);
  const double ty = tx / aspect;
  sim::Drops& d = frame.drops;
  d.id.resize(count);
  d.position.resize(count);
  d.velocity.resize(count);
  d.acceleration.assign(count, glm::vec3{0.0f});
  d.diameter.resize(count);
  d.age.assign(count, 1.0f);
  d.vanishing_rate.assign(count, 0.0f);
  d.opacity.assign(count, 1.0f);
  d.colour.assign(count, glm::vec3{0.9f, 0.95f, 1.0f});
  constexpr double kNear = 0.3;
  for (std::size_t i = 0; i < count; ++i) {
    // Uniform in volume: depth ∝ cube root, so far slices hold as many drops per m³.
    const double z3 = kNear * kNear * kNear +
                      uniform(seed, i, 0) * (far_m * far_m * far_m - kNear * kNear * kNear);
    const double z = std::cbrt(z3);
    const double x = (2.0 * uniform(seed, i, 1) - 1.0) * z * tx;
    const double y = (2.0 * uniform(seed, i, 2) - 1.0) * z * ty;
    const double diameter_m = (0.5 + 2.5 * uniform(seed, i, 3)) * 1e-3;
    d.id[i] = i;
    d.position[i] = glm::vec3(camera.position + forward * z + right * x + up * y);
    d.velocity[i] = glm::vec3(static_cast<float>(wind_x_m_per_s),
                              static_cast<float>(-sim::terminal_velocity(diameter_m)), 0.0f);
    d.diameter[i] = static_cast<float>(diameter_m);
  }
  return frame;
}

}  // namespace raintrace::povgen::test_support
