// The camera's view frustum between near and far distances: what drops must fill, what a
// snapshot keeps, and the box of air the World simulates around it.
#pragma once

#include <array>
#include <glm/vec3.hpp>

#include "sim/camera.h"

namespace raintrace::sim {

class ViewVolume {
 public:
  /// Throws std::invalid_argument if the camera looks at its own position.
  ViewVolume(const Camera& camera, double near_m, double far_m);

  /// True if p is inside the frustum with near_m <= depth <= far_m. False for NaN.
  [[nodiscard]] bool contains(const glm::dvec3& p) const;
  /// Exact frustum volume, m³: (4·tan(h/2)·tan(v/2))·(far³ − near³)/3.
  [[nodiscard]] double volume_m3() const { return m_volume; }
  /// The 8 corners (near plane first), metres.
  [[nodiscard]] const std::array<glm::dvec3, 8>& corners() const { return m_corners; }
  [[nodiscard]] const glm::dvec3& eye() const { return m_eye; }
  [[nodiscard]] const glm::dvec3& forward() const { return m_forward; }
  [[nodiscard]] const glm::dvec3& right() const { return m_right; }
  [[nodiscard]] const glm::dvec3& up() const { return m_up; }

 private:
  glm::dvec3 m_eye{}, m_forward{}, m_right{}, m_up{};
  double m_tan_h = 0.0, m_tan_v = 0.0, m_near = 0.0, m_far = 0.0, m_volume = 0.0;
  std::array<glm::dvec3, 8> m_corners{};
};

}  // namespace raintrace::sim
