// Synthetic rain: a counter-based hash per drop, so drop i is the same whatever the count.
#include "povgen/synthetic_rain.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace raintrace::povgen {
namespace {

/// SplitMix64 finaliser: a well-mixed 64-bit value from a counter.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

double uniform(std::uint64_t seed, std::uint64_t id, std::uint64_t k) {
  return static_cast<double>(mix(seed ^ mix(id * 8 + k)) >> 11) * 0x1.0p-53;
}

}  // namespace

sim::Frame synthetic_rain(std::size_t count, const sim::Camera& camera, double aspect, double far_m,
                          double wind_x_m_per_s, std::uint64_t seed) {
  sim::Frame frame;
  frame.index = 1;
  const glm::dvec3 forward = glm::normalize(camera.look_at - camera.position);
  const glm::dvec3 right = glm::normalize(glm::cross(glm::dvec3{0, 1, 0}, forward));
  const glm::dvec3 up = glm::cross(forward, right);
  const double tx = std::tan(camera.fov_deg * 0.5 * 3.14159265358979323846 / 180.0);
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
  for (std::size_t i = 0; i < count; ++i) {
    // Uniform in volume: depth ∝ cube root, so far slices hold as many drops per m³.
    const double near = 0.3;
    const double z3 =
        near * near * near + uniform(seed, i, 0) * (far_m * far_m * far_m - near * near * near);
    const double z = std::cbrt(z3);
    const double x = (2.0 * uniform(seed, i, 1) - 1.0) * z * tx;
    const double y = (2.0 * uniform(seed, i, 2) - 1.0) * z * ty;
    const double diameter_mm = 0.5 + 2.5 * uniform(seed, i, 3);
    const double terminal = 9.65 - 10.3 * std::exp(-0.6 * diameter_mm);  // Atlas et al. 1973
    d.id[i] = i;
    d.position[i] = glm::vec3(camera.position + forward * z + right * x + up * y);
    d.velocity[i] =
        glm::vec3(static_cast<float>(wind_x_m_per_s), static_cast<float>(-terminal), 0.0f);
    d.diameter[i] = static_cast<float>(diameter_mm * 1e-3);
  }
  return frame;
}

}  // namespace raintrace::povgen
