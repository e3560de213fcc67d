// Splash droplets (see splash.h).
#include "sim/splash.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "sim/random.h"
#include "sim/terminal_velocity.h"

namespace raintrace::sim {

void emit_splash(SplashState& state, const SplashParams& params, const glm::vec3& hit,
                 const glm::vec3& impact_velocity, float diameter_m, std::uint64_t drop_id,
                 std::uint64_t seed) {
  const float speed = glm::length(impact_velocity);
  for (int k = 0; k < params.droplets; ++k) {
    auto u = [&](int dim) {
      return static_cast<float>(uniform(seed, Stream::splash, drop_id, k * 8 + dim));
    };
    const float azimuth = 2.0f * std::numbers::pi_v<float> * u(0);
    const float up = speed * (0.1f + 0.25f * u(1));
    const float out = speed * (0.1f + 0.3f * u(2));
    glm::vec3 v{out * std::cos(azimuth), up, out * std::sin(azimuth)};
    // Part of the drop's sideways momentum carries into the crown.
    v.x += 0.3f * impact_velocity.x;
    v.z += 0.3f * impact_velocity.z;
    state.droplets.position.push_back(hit + glm::vec3{0.0f, 1e-4f, 0.0f});
    state.droplets.velocity.push_back(v);
    state.droplets.diameter.push_back(diameter_m * (0.1f + 0.2f * u(3)));
    state.droplets.opacity.push_back(1.0f);
    state.age.push_back(0.0f);
  }
}

void step_splashes(SplashState& state, const SplashParams& params, float dt, float ground_y) {
  auto& d = state.droplets;
  const auto lifetime = static_cast<float>(params.lifetime_s);
  const auto g = static_cast<float>(kGravity);
  std::size_t keep = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    glm::vec3 v = d.velocity[i];
    v.y -= g * dt;
    const glm::vec3 p = d.position[i] + dt * v;
    const float age = state.age[i] + dt;
    if (age >= lifetime || !(p.y >= ground_y)) continue;
    // Compact in place, keeping order (deterministic).
    d.position[keep] = p;
    d.velocity[keep] = v;
    d.diameter[keep] = d.diameter[i];
    d.opacity[keep] = 1.0f - age / lifetime;
    state.age[keep] = age;
    ++keep;
  }
  d.position.resize(keep);
  d.velocity.resize(keep);
  d.diameter.resize(keep);
  d.opacity.resize(keep);
  state.age.resize(keep);
}

}  // namespace raintrace::sim
