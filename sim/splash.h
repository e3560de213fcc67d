// Splash droplets: a drop that hits the ground throws `droplets` small droplets up and out;
// they fly ballistically (gravity only — they are short-lived and slow, so drag is negligible
// over their lifetime) and fade linearly over lifetime_s.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "sim/frame.h"
#include "sim/params.h"

namespace raintrace::sim {

struct SplashState {
  SplashDroplets droplets;
  std::vector<float> age;  ///< s since the splash

  [[nodiscard]] std::size_t size() const { return droplets.size(); }
};

/// Adds the droplets of one impact. The crown throws droplets at a fraction of the impact
/// speed (about 0.1–0.35 upward, 0.1–0.4 sideways) with diameters 0.1–0.3 of the drop's;
/// random numbers keyed by the drop's id.
void emit_splash(SplashState& state, const SplashParams& params, const glm::vec3& hit,
                 const glm::vec3& impact_velocity, float diameter_m, std::uint64_t drop_id,
                 std::uint64_t seed);

/// Advances all droplets by dt; removes those past lifetime_s or below the ground.
void step_splashes(SplashState& state, const SplashParams& params, float dt, float ground_y);

}  // namespace raintrace::sim
