// Frustum planes from the camera (the plane tests are inline in the header).
#include "povgen/view_frustum.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <stdexcept>

namespace raintrace::povgen {

ViewFrustum::ViewFrustum(const sim::Camera& camera, double aspect) {
  const glm::dvec3 forward = camera.look_at - camera.position;
  const double length = glm::length(forward);
  if (!std::isfinite(length) || length <= 0.0 || !std::isfinite(aspect) || aspect <= 0.0 ||
      !(camera.fov_deg > 0.0 && camera.fov_deg < 180.0)) {
    throw std::invalid_argument(
        "camera: position and look_at must differ, fov in (0, 180) and aspect > 0");
  }
  m_eye = glm::vec3(camera.position);
  m_forward = glm::vec3(forward / length);
  // POV-Ray's look_at keeps `sky` (+y) up; looking straight up or down falls back to +z as sky.
  glm::vec3 sky{0.0f, 1.0f, 0.0f};
  if (std::fabs(glm::dot(sky, m_forward)) > 0.9999f) sky = {0.0f, 0.0f, 1.0f};
  m_right = glm::normalize(glm::cross(sky, m_forward));  // left-handed: y × z = x
  m_up = glm::cross(m_forward, m_right);
  m_tan_half_x = static_cast<float>(std::tan(camera.fov_deg * 0.5 * std::numbers::pi / 180.0));
  const float tan_half_y = m_tan_half_x / static_cast<float>(aspect);
  // A point is inside the left plane when x ≥ −z·tx, i.e. dot(p, right + tx·forward) ≥ 0.
  m_normals[0] = glm::normalize(m_right + m_tan_half_x * m_forward);
  m_normals[1] = glm::normalize(-m_right + m_tan_half_x * m_forward);
  m_normals[2] = glm::normalize(m_up + tan_half_y * m_forward);
  m_normals[3] = glm::normalize(-m_up + tan_half_y * m_forward);
}

}  // namespace raintrace::povgen
