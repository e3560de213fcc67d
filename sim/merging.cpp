// Grid-based merging pass (see merging.h).
#include "sim/merging.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "sim/breakup.h"

namespace raintrace::sim {
namespace {

constexpr std::int64_t kMaxColumnsPerAxis = 4096;

// Moves drop j's water and momentum into drop i.
void coalesce(Drops& d, std::size_t i, std::size_t j) {
  const float di = d.diameter[i], dj = d.diameter[j];
  const float vi = di * di * di, vj = dj * dj * dj, v = vi + vj;
  const float wi = vi / v, wj = vj / v;
  d.position[i] = wi * d.position[i] + wj * d.position[j];
  d.velocity[i] = wi * d.velocity[i] + wj * d.velocity[j];
  d.colour[i] = wi * d.colour[i] + wj * d.colour[j];
  d.opacity[i] = wi * d.opacity[i] + wj * d.opacity[j];
  d.vanishing_rate[i] = wi * d.vanishing_rate[i] + wj * d.vanishing_rate[j];
  d.age[i] = std::max(d.age[i], d.age[j]);
  if (dj > di) d.id[i] = d.id[j];
  d.diameter[i] = std::cbrt(v);
}

template <typename T>
void compact(std::vector<T>& v, const std::vector<std::uint8_t>& dead) {
  std::size_t keep = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!dead[i]) v[keep++] = v[i];
  }
  v.resize(keep);
}

// The relative-velocity bound of merging.h, measured from the drops.
MergeBounds measure_bounds(const Drops& d, float window, const Wind* wind, double time_s) {
  constexpr float kBig = std::numeric_limits<float>::max();
  glm::vec3 v_lo{kBig}, v_hi{-kBig}, s_lo{kBig}, s_hi{-kBig};
  float touch = 0.0f;
  const bool turbulent = wind != nullptr && wind->has_turbulence();
  for (std::size_t i = 0; i < d.size(); ++i) {
    const glm::vec3 v = d.velocity[i];
    const glm::vec3 s = turbulent ? v - wind->turbulence_at(d.position[i], time_s) : v;
    v_lo = glm::min(v_lo, v), v_hi = glm::max(v_hi, v);
    s_lo = glm::min(s_lo, s), s_hi = glm::max(s_hi, s);
    touch = std::max(touch, d.diameter[i]);
  }
  MergeBounds b;
  b.touch_m = touch;
  // Without turbulence the slip is the velocity and the bound its spread; with it, the
  // velocity spread over the whole box is always valid, the slip bound usually much tighter.
  b.dv_m_per_s = v_hi - v_lo;
  if (turbulent) {
    const glm::vec3 slip = s_hi - s_lo;
    const auto lip = static_cast<float>(wind->turbulence_lipschitz_per_s());
    // Touching drops were at most touch + |Δv|·W apart now, so |Δv| <= L·(touch + |Δv|·W) + |Δs|.
    if (lip * window < 0.5f) {
      const float speed = (lip * touch + glm::length(slip)) / (1.0f - lip * window);
      b.dv_m_per_s = glm::min(b.dv_m_per_s, slip + lip * (touch + speed * window));
    }
  }
  // Float rounding in the test below must never beat the bound.
  b.dv_m_per_s = b.dv_m_per_s * 1.01f + 1e-3f;
  b.touch_m = touch * 1.01f;
  b.column_m = b.touch_m + 0.5f * window * std::max(b.dv_m_per_s.x, b.dv_m_per_s.z);
  b.vertical_m = b.touch_m + 0.5f * window * b.dv_m_per_s.y;
  return b;
}

}  // namespace

MergeResult merge_touching(DropState& state, float interval_s, double breakup_diameter_m,
                           std::uint64_t& next_id, std::uint64_t seed, const Wind* wind,
                           double time_s, MergeBounds* bounds) {
  MergeResult result;
  Drops& d = state.drops;
  const std::size_t n = d.size();
  if (n < 2) return result;
  const MergeBounds b = measure_bounds(d, interval_s, wind, time_s);
  if (bounds != nullptr) *bounds = b;
  // Candidates are binned by their positions in the middle of the interval.
  const float half = 0.5f * interval_s;
  std::vector<glm::vec3> mid(n);
  for (std::size_t i = 0; i < n; ++i) mid[i] = d.position[i] - half * d.velocity[i];
  constexpr float kBig = std::numeric_limits<float>::max();
  float x0 = kBig, x1 = -kBig, z0 = kBig, z1 = -kBig;
  for (const glm::vec3& p : mid) {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
    z0 = std::min(z0, p.z), z1 = std::max(z1, p.z);
  }
  // No more columns than drops: finer grids only add empty columns to clear and scan (and
  // memory), hardly fewer candidates. The result is the same whatever the column size.
  const float by_count = std::sqrt((x1 - x0) * (z1 - z0) / static_cast<float>(n));
  const float cell = std::max(
      {b.column_m, by_count, (x1 - x0) / kMaxColumnsPerAxis, (z1 - z0) / kMaxColumnsPerAxis});
  const auto nx = static_cast<std::int64_t>((x1 - x0) / cell) + 1;
  const auto nz = static_cast<std::int64_t>((z1 - z0) / cell) + 1;
  auto column_x = [&](const glm::vec3& p) {
    return std::clamp<std::int64_t>(static_cast<std::int64_t>((p.x - x0) / cell), 0, nx - 1);
  };
  auto column_z = [&](const glm::vec3& p) {
    return std::clamp<std::int64_t>(static_cast<std::int64_t>((p.z - z0) / cell), 0, nz - 1);
  };
  // Counting sort by column; ascending drop index within a column.
  std::vector<std::uint32_t> column(n), start(static_cast<std::size_t>(nx * nz) + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    column[i] = static_cast<std::uint32_t>(column_x(mid[i]) + nx * column_z(mid[i]));
    ++start[column[i] + 1];
  }
  for (std::size_t c = 0; c + 1 < start.size(); ++c) start[c + 1] += start[c];
  std::vector<std::uint32_t> sorted_index(n);
  std::vector<glm::vec3> sorted_mid(n);
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t k = fill[column[i]]++;
      sorted_index[k] = static_cast<std::uint32_t>(i);
      sorted_mid[k] = mid[i];
    }
  }
  std::vector<std::uint8_t> dead(n, 0), grown(n, 0);
  const float reach_x = b.touch_m + half * b.dv_m_per_s.x;
  const float reach_z = b.touch_m + half * b.dv_m_per_s.z;
  // Walk drops column by column so neighbouring columns are in cache; the pair rule j > i
  // still tests each pair once, and the walk order is fixed, so results are deterministic.
  for (std::size_t walk = 0; walk < n; ++walk) {
    const std::size_t i = sorted_index[walk];
    if (dead[i]) continue;
    const glm::vec3 mi = sorted_mid[walk];
    const std::int64_t cx = column_x(mi), cz = column_z(mi);
    const std::int64_t xa = std::max<std::int64_t>(cx - 1, 0), xb = std::min(cx + 1, nx - 1);
    for (std::int64_t z = std::max<std::int64_t>(cz - 1, 0); z <= std::min(cz + 1, nz - 1); ++z) {
      // Columns xa..xb of row z are one contiguous run of the sorted arrays.
      const std::uint32_t k0 = start[static_cast<std::size_t>(xa + nx * z)];
      const std::uint32_t k1 = start[static_cast<std::size_t>(xb + nx * z) + 1];
      for (std::uint32_t k = k0; k < k1; ++k) {
        const glm::vec3 dm = sorted_mid[k] - mi;
        if (std::abs(dm.y) > b.vertical_m || std::abs(dm.x) > reach_x || std::abs(dm.z) > reach_z) {
          continue;
        }
        const std::uint32_t j = sorted_index[k];
        if (j <= i || dead[j]) continue;
        const glm::vec3 dp = d.position[j] - d.position[i];
        const glm::vec3 dv = d.velocity[j] - d.velocity[i];
        const float window = std::min({interval_s, d.age[i], d.age[j]});
        const float vv = glm::dot(dv, dv);
        // Closest approach at τ in [−window, 0] of dp + dv·τ.
        const float tau = vv > 0.0f ? std::clamp(-glm::dot(dp, dv) / vv, -window, 0.0f) : 0.0f;
        const glm::vec3 gap = dp + dv * tau;
        const float touch = 0.5f * (d.diameter[i] + d.diameter[j]);
        if (glm::dot(gap, gap) <= touch * touch) {
          coalesce(d, i, j);
          dead[j] = 1;
          grown[i] = 1;
          ++result.merges;
        }
      }
    }
    if (grown[i]) state.refresh_drag(i);
  }
  if (result.merges == 0) return result;
  for (std::size_t i = 0; i < n; ++i) {
    if (grown[i] && !dead[i]) {
      const std::size_t added = break_up(state, i, breakup_diameter_m, next_id, seed);
      if (added > 0) ++result.breakups;
      dead.resize(dead.size() + added, 0);
    }
  }
  compact(d.id, dead);
  compact(d.position, dead);
  compact(d.velocity, dead);
  compact(d.acceleration, dead);
  compact(d.diameter, dead);
  compact(d.age, dead);
  compact(d.vanishing_rate, dead);
  compact(d.opacity, dead);
  compact(d.colour, dead);
  compact(state.drag, dead);
  return result;
}

}  // namespace raintrace::sim
