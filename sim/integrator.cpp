// The hot loop (see integrator.h): no allocation, no branches in the arithmetic; the only
// branch is the rarely taken event push.
#include "sim/integrator.h"

#include <cmath>

#include "sim/terminal_velocity.h"

namespace raintrace::sim {

void integrate_range(DropState& state, std::size_t begin, std::size_t end, const StepConstants& c,
                     StepEvents& events) {
  glm::vec3* __restrict pos = state.drops.position.data();
  glm::vec3* __restrict vel = state.drops.velocity.data();
  glm::vec3* __restrict acc = state.drops.acceleration.data();
  float* __restrict age = state.drops.age.data();
  float* __restrict opacity = state.drops.opacity.data();
  const float* __restrict rate = state.drops.vanishing_rate.data();
  const float* __restrict drag = state.drag.data();
  const float dt = c.dt, inv_dt = 1.0f / c.dt;
  const auto g = static_cast<float>(kGravity);
  const bool turbulent = c.turbulence != nullptr;
  const bool fading = c.fading;
  for (std::size_t i = begin; i < end; ++i) {
    const glm::vec3 p = pos[i], v = vel[i];
    glm::vec3 w = c.wind;
    if (turbulent) w += c.turbulence->turbulence_at(p, c.time_s);
    const glm::vec3 u = w - v;
    const float ku = drag[i] * std::sqrt(u.x * u.x + u.y * u.y + u.z * u.z);
    const float inv = 1.0f / (1.0f + ku * dt);
    const glm::vec3 vn{(v.x + dt * ku * w.x) * inv, (v.y + dt * (ku * w.y - g)) * inv,
                       (v.z + dt * ku * w.z) * inv};
    const glm::vec3 pn = p + dt * vn;
    acc[i] = (vn - v) * inv_dt;
    vel[i] = vn;
    pos[i] = pn;
    age[i] += dt;
    const float o = fading ? opacity[i] / (1.0f + rate[i] * dt) : opacity[i];
    if (fading) opacity[i] = o;
    const float rx = pn.x - c.origin.x, rz = pn.z - c.origin.z;
    const float a = rx * c.across.x + rz * c.across.z;
    const float b = rx * c.along.x + rz * c.along.z;
    // Written so that NaN anywhere makes `inside` false and the drop leaves.
    const bool inside =
        a >= c.a0 && a <= c.a1 && b >= c.b0 && b <= c.b1 && pn.y <= c.ceiling && o >= c.min_opacity;
    const bool above_ground = pn.y > c.ground;
    if (!(inside && above_ground)) [[unlikely]] {
      const auto idx = static_cast<std::uint32_t>(i);
      if (inside) {
        events.ground.push_back(idx);
      } else {
        events.gone.push_back(idx);
      }
    }
  }
}

}  // namespace raintrace::sim
