// Drop breakup (see breakup.h).
#include "sim/breakup.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "sim/random.h"

namespace raintrace::sim {
namespace {
constexpr int kMaxFragments = 16;
/// Sideways speed at which the fragments of a breaking drop fly apart, m/s.
constexpr float kFragmentSpeed_m_per_s = 0.3f;
}  // namespace

std::size_t break_up(DropState& state, std::size_t i, double breakup_diameter_m,
                     std::uint64_t& next_id, std::uint64_t seed) {
  const double d = state.drops.diameter[i];
  if (!(d > breakup_diameter_m)) return 0;
  const double volume = d * d * d;  // in units of π/6
  const double critical = breakup_diameter_m * breakup_diameter_m * breakup_diameter_m;
  const int n = std::clamp(static_cast<int>(std::ceil(2.0 * volume / critical)), 2, kMaxFragments);
  const std::uint64_t parent = state.drops.id[i];
  std::vector<double> weight(n);
  double total = 0.0;
  for (int k = 0; k < n; ++k) {
    weight[k] = 0.75 + 0.5 * uniform(seed, Stream::breakup, parent, k * 8);
    total += weight[k];
  }
  NewDrop base;
  base.position = state.drops.position[i];
  base.velocity = state.drops.velocity[i];
  base.vanishing_rate = state.drops.vanishing_rate[i];
  base.opacity = state.drops.opacity[i];
  base.colour = state.drops.colour[i];
  for (int k = 0; k < n; ++k) {
    const auto dk = static_cast<float>(std::cbrt(volume * weight[k] / total));
    const double az = 2.0 * std::numbers::pi * uniform(seed, Stream::breakup, parent, k * 8 + 1);
    const glm::vec3 dir{static_cast<float>(std::cos(az)), 0.0f, static_cast<float>(std::sin(az))};
    // Fragments fly apart sideways at kFragmentSpeed, starting a parent diameter apart.
    const glm::vec3 offset = dir * static_cast<float>(d) * static_cast<float>(k > 0 ? 1 : 0);
    if (k == 0) {
      state.drops.diameter[i] = dk;
      state.drops.age[i] = 0.0f;
      state.drops.velocity[i] += dir * kFragmentSpeed_m_per_s;
      state.refresh_drag(i);
      continue;
    }
    NewDrop f = base;
    f.id = next_id++;
    f.diameter = dk;
    f.position = base.position + offset;
    f.velocity = base.velocity + dir * kFragmentSpeed_m_per_s;
    f.age = 0.0f;
    state.push(f);
  }
  return static_cast<std::size_t>(n - 1);
}

}  // namespace raintrace::sim
