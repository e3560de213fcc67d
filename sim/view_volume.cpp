// View frustum geometry (see view_volume.h). POV-Ray is left-handed with +y up and +z into the
// screen, so right = up × forward.
#include "sim/view_volume.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <stdexcept>

namespace raintrace::sim {

ViewVolume::ViewVolume(const Camera& camera, double near_m, double far_m)
    : m_eye(camera.position), m_near(near_m), m_far(far_m) {
  const glm::dvec3 dir = camera.look_at - camera.position;
  if (!(glm::length(dir) > 0.0)) {
    throw std::invalid_argument("camera.look_at must differ from camera.position");
  }
  m_forward = glm::normalize(dir);
  // Looking straight up or down: any horizontal "up" will do.
  const glm::dvec3 world_up =
      std::abs(m_forward.y) > 0.999 ? glm::dvec3{0.0, 0.0, 1.0} : glm::dvec3{0.0, 1.0, 0.0};
  m_right = glm::normalize(glm::cross(world_up, m_forward));
  m_up = glm::cross(m_forward, m_right);
  m_tan_h = std::tan(camera.fov_deg * std::numbers::pi / 360.0);
  m_tan_v = m_tan_h / camera.aspect;
  m_volume = 4.0 * m_tan_h * m_tan_v * (far_m * far_m * far_m - near_m * near_m * near_m) / 3.0;
  int c = 0;
  for (const double d : {near_m, far_m}) {
    for (const double sy : {-1.0, 1.0}) {
      for (const double sx : {-1.0, 1.0}) {
        m_corners[c++] = m_eye + d * (m_forward + sx * m_tan_h * m_right + sy * m_tan_v * m_up);
      }
    }
  }
}

bool ViewVolume::contains(const glm::dvec3& p) const {
  const glm::dvec3 q = p - m_eye;
  const double f = glm::dot(q, m_forward);
  const double r = glm::dot(q, m_right);
  const double u = glm::dot(q, m_up);
  return f >= m_near && f <= m_far && std::abs(r) <= f * m_tan_h && std::abs(u) <= f * m_tan_v;
}

}  // namespace raintrace::sim
