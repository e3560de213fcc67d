// One substep of drop motion: p = p' + ∫v, v = v' + ∫a, a = G + k·|u|·u with u = wind − v
// (quadratic drag toward the local wind). The drag is treated implicitly with k·|u| frozen
// over the substep, v' = (v + dt·(G + k|u|·w)) / (1 + k|u|·dt), which is unconditionally
// stable for any substep and has the exact terminal velocity as its fixed point.
// Pure per drop, so any split into chunks gives bit-identical results.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "sim/drop_state.h"
#include "sim/wind.h"

namespace raintrace::sim {

struct StepConstants {
  float dt = 0.002f;                 ///< s
  double time_s = 0.0;               ///< start of the substep
  glm::vec3 wind{0.0f};              ///< steady + gust at time_s, m/s
  const Wind* turbulence = nullptr;  ///< non-null only if turbulence is on
  // The simulated box in the yaw frame (see spawn_region.h).
  glm::vec3 origin{0.0f};
  glm::vec3 across{1.0f, 0.0f, 0.0f};
  glm::vec3 along{0.0f, 0.0f, 1.0f};
  float a0 = 0, a1 = 0, b0 = 0, b1 = 0, ground = 0, ceiling = 0;
  // Within the box, a drop h above the ground with terminal speed v_t stays only while it can
  // still reach the footprint [fa0, fa1] × [fb0, fb1] before the ground: at most h·e/v_t
  // beyond each side, e the side's drift speed bound (see spawn_region.h).
  float fa0 = 0, fa1 = 0, fb0 = 0, fb1 = 0;
  float ea0 = 0, ea1 = 0, eb0 = 0, eb1 = 0;  ///< m/s, >= 0
  float min_opacity = 0.0f;                  ///< drops faded below this leave
  bool fading = false;  ///< any drop has a vanishing rate > 0 (else opacity stays put)
};

/// Indices (ascending) of drops that reached the ground, and of drops that left otherwise.
struct StepEvents {
  std::vector<std::uint32_t> ground;
  std::vector<std::uint32_t> gone;
  void clear() {
    ground.clear();
    gone.clear();
  }
};

/// Advances drops [begin, end) by one substep and appends their events.
void integrate_range(DropState& state, std::size_t begin, std::size_t end, const StepConstants& c,
                     StepEvents& events);

}  // namespace raintrace::sim
