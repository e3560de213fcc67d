// Simulated box around the view (see spawn_region.h).
#include "sim/spawn_region.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

namespace raintrace::sim {
namespace {
// Upwind extension cap: beyond this the drops would spend their whole life out of view.
constexpr double kMaxExtensionM = 300.0;
}  // namespace

SpawnRegion::SpawnRegion(const ViewVolume& view, double ground_y_m, double ceiling_margin_m,
                         const glm::dvec3& wind_h, double wind_spread, double slowest_fall_m_per_s)
    : m_origin(view.eye().x, 0.0, view.eye().z), m_ground(ground_y_m) {
  glm::dvec3 fwd{view.forward().x, 0.0, view.forward().z};
  m_along = glm::length(fwd) > 1e-9 ? glm::normalize(fwd) : glm::dvec3{0.0, 0.0, 1.0};
  m_across = glm::dvec3{m_along.z, 0.0, -m_along.x};
  double a0 = std::numeric_limits<double>::max(), a1 = -a0, b0 = a0, b1 = -a0, top = -a0;
  for (const glm::dvec3& c : view.corners()) {
    a0 = std::min(a0, across(c));
    a1 = std::max(a1, across(c));
    b0 = std::min(b0, along(c));
    b1 = std::max(b1, along(c));
    top = std::max(top, c.y);
  }
  m_ma0 = a0, m_ma1 = a1, m_mb0 = b0, m_mb1 = b1;
  m_ceiling = std::max(top, ground_y_m) + ceiling_margin_m;
  // A frustum entirely below the ground still gets a thin layer of air to rain through.
  if (m_ceiling <= m_ground) m_ceiling = m_ground + std::max(ceiling_margin_m, 1.0);
  const double fall_time = (m_ceiling - m_ground) / std::max(slowest_fall_m_per_s, 0.1);
  const double wa = glm::dot(wind_h, m_across), wb = glm::dot(wind_h, m_along);
  // Wind blowing toward +a carries drops in from the −a side: extend that side.
  m_ea0 = std::max(0.0, wa + wind_spread);
  m_ea1 = std::max(0.0, -wa + wind_spread);
  m_eb0 = std::max(0.0, wb + wind_spread);
  m_eb1 = std::max(0.0, -wb + wind_spread);
  auto extend = [&](double e) { return std::min(kMaxExtensionM, fall_time * e); };
  m_a0 = a0 - extend(m_ea0);
  m_a1 = a1 + extend(m_ea1);
  m_b0 = b0 - extend(m_eb0);
  m_b1 = b1 + extend(m_eb1);
}

double SpawnRegion::reachable_volume_m3(double fall_m_per_s) const {
  // The reachable rectangle grows linearly with height, clipped to the box: its area is
  // piecewise quadratic in y, and midpoints of 256 slices integrate it well within 0.1 %.
  constexpr int kSlices = 256;
  const double dy = (m_ceiling - m_ground) / kSlices;
  double volume = 0.0;
  for (int k = 0; k < kSlices; ++k) {
    const double reach = (k + 0.5) * dy / fall_m_per_s;  // time to the ground, s
    const double a = std::min(m_a1, m_ma1 + reach * m_ea1) - std::max(m_a0, m_ma0 - reach * m_ea0);
    const double b = std::min(m_b1, m_mb1 + reach * m_eb1) - std::max(m_b0, m_mb0 - reach * m_eb0);
    volume += std::max(0.0, a) * std::max(0.0, b) * dy;
  }
  return volume;
}

bool SpawnRegion::reaches_footprint(double a, double b, double y, double fall_m_per_s) const {
  const double reach = (y - m_ground) / fall_m_per_s;  // time to the ground, s
  return a >= m_ma0 - reach * m_ea0 && a <= m_ma1 + reach * m_ea1 && b >= m_mb0 - reach * m_eb0 &&
         b <= m_mb1 + reach * m_eb1;
}

glm::dvec3 SpawnRegion::point(double a, double b, double y) const {
  glm::dvec3 p = m_origin + a * m_across + b * m_along;
  p.y = y;
  return p;
}

double SpawnRegion::across(const glm::dvec3& p) const {
  return (p.x - m_origin.x) * m_across.x + (p.z - m_origin.z) * m_across.z;
}

double SpawnRegion::along(const glm::dvec3& p) const {
  return (p.x - m_origin.x) * m_along.x + (p.z - m_origin.z) * m_along.z;
}

bool SpawnRegion::in_measure_area(const glm::dvec3& p) const {
  const double a = across(p), b = along(p);
  return a >= m_ma0 && a <= m_ma1 && b >= m_mb0 && b <= m_mb1;
}

}  // namespace raintrace::sim
