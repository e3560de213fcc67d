// The box of air the World simulates: in the camera's horizontal (yaw) frame, the bounding
// rectangle of the view frustum's footprint, extended upwind by how far wind can carry the
// slowest drop while it falls from the ceiling to the ground — so wind-blown rain enters the
// view already at the right density — and vertically from the ground to a ceiling
// `ceiling_margin_m` above the frustum's highest point. Drops are born on the ceiling and die
// when they reach the ground or leave the box.
// Only part of the upwind extension matters for a given drop: at height h above the ground, a
// drop with terminal speed v_t drifts at most h·e/v_t sideways before it lands (e the drift
// speed bound toward that side), so farther out it can never reach the footprint — nor the
// view above it. Such drops are not created (fill, spawn) and leave as soon as they get there
// (integrator), which cuts the simulated drops by the wedge above the extension's ground and
// by most of it for large, fast drops.
#pragma once

#include <glm/vec3.hpp>

#include "sim/view_volume.h"

namespace raintrace::sim {

class SpawnRegion {
 public:
  /// wind_h is the steady horizontal wind (m/s), wind_spread a bound on how far gusts and
  /// turbulence add to it in any direction (m/s), slowest_fall_m_per_s the smallest drop's
  /// terminal velocity.
  SpawnRegion(const ViewVolume& view, double ground_y_m, double ceiling_margin_m,
              const glm::dvec3& wind_h, double wind_spread, double slowest_fall_m_per_s);

  /// World position of yaw-frame coordinates (a across, b along the view) at height y.
  [[nodiscard]] glm::dvec3 point(double a, double b, double y) const;
  /// Yaw-frame coordinates (a, b) of a world position.
  [[nodiscard]] double across(const glm::dvec3& p) const;
  [[nodiscard]] double along(const glm::dvec3& p) const;

  /// Horizontal area drops are born over, m² (the extended rectangle).
  [[nodiscard]] double spawn_area_m2() const { return (m_a1 - m_a0) * (m_b1 - m_b0); }
  /// Air volume of the box, m³.
  [[nodiscard]] double volume_m3() const { return spawn_area_m2() * (m_ceiling - m_ground); }
  /// Of that box, the air from which a drop falling at fall_m_per_s can still reach the
  /// footprint (reaches_footprint), m³: the volume such drops fill. In wind it is a wedge of the
  /// box, about half of it for the slowest drops and less for faster ones.
  [[nodiscard]] double reachable_volume_m3(double fall_m_per_s) const;
  /// The unextended footprint rectangle, where ground water is measured, m².
  [[nodiscard]] double measure_area_m2() const { return (m_ma1 - m_ma0) * (m_mb1 - m_mb0); }
  [[nodiscard]] bool in_measure_area(const glm::dvec3& p) const;
  /// True if a drop at yaw-frame (a, b), height y, falling at fall_m_per_s can still drift
  /// onto the footprint before reaching the ground (see above).
  [[nodiscard]] bool reaches_footprint(double a, double b, double y, double fall_m_per_s) const;

  /// The footprint rectangle (where ground water is measured) in the yaw frame.
  [[nodiscard]] double fa0() const { return m_ma0; }
  [[nodiscard]] double fa1() const { return m_ma1; }
  [[nodiscard]] double fb0() const { return m_mb0; }
  [[nodiscard]] double fb1() const { return m_mb1; }
  /// Bounds of the sideways drift speed onto the footprint from each side, m/s, >= 0: a drop
  /// beyond fa0 moves toward +a at most ea0, one beyond fa1 toward −a at most ea1, etc.
  [[nodiscard]] double ea0() const { return m_ea0; }
  [[nodiscard]] double ea1() const { return m_ea1; }
  [[nodiscard]] double eb0() const { return m_eb0; }
  [[nodiscard]] double eb1() const { return m_eb1; }

  [[nodiscard]] double ground() const { return m_ground; }
  [[nodiscard]] double ceiling() const { return m_ceiling; }
  [[nodiscard]] double a0() const { return m_a0; }
  [[nodiscard]] double a1() const { return m_a1; }
  [[nodiscard]] double b0() const { return m_b0; }
  [[nodiscard]] double b1() const { return m_b1; }
  [[nodiscard]] const glm::dvec3& origin() const { return m_origin; }
  [[nodiscard]] const glm::dvec3& across_axis() const { return m_across; }
  [[nodiscard]] const glm::dvec3& along_axis() const { return m_along; }

 private:
  glm::dvec3 m_origin{}, m_across{1, 0, 0}, m_along{0, 0, 1};
  double m_a0 = 0, m_a1 = 0, m_b0 = 0, m_b1 = 0;      // simulated rectangle
  double m_ma0 = 0, m_ma1 = 0, m_mb0 = 0, m_mb1 = 0;  // measured rectangle
  double m_ea0 = 0, m_ea1 = 0, m_eb0 = 0, m_eb1 = 0;  // drift speed bounds, m/s
  double m_ground = 0, m_ceiling = 0;
};

}  // namespace raintrace::sim
