// The camera's view as four side planes and a near plane: what is outside is not written.
// Same construction as POV-Ray's `camera { location look_at right x*aspect angle fov }`, so a
// culled drop is one POV-Ray would not have shown.
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "sim/camera.h"

namespace raintrace::povgen {

class ViewFrustum {
 public:
  /// aspect = image width / height; horizontal field of view from camera.fov_deg.
  /// Throws std::invalid_argument when position == look_at or the numbers are not finite.
  ViewFrustum(const sim::Camera& camera, double aspect);

  /// True unless the sphere lies wholly outside one of the planes (conservative: a sphere
  /// near a frustum corner may be kept, a visible one is never dropped).
  [[nodiscard]] bool sphere_visible(const glm::vec3& centre, float radius) const;
  /// True unless the segment a–b, thickened by margin, lies wholly outside one plane.
  [[nodiscard]] bool segment_visible(const glm::vec3& a, const glm::vec3& b, float margin) const;
  /// Distance along the view direction (camera depth), metres.
  [[nodiscard]] float depth(const glm::vec3& point) const;
  /// Width of one pixel at camera depth `depth_m`, metres, for an image `width_px` wide.
  [[nodiscard]] float pixel_size(float depth_m, int width_px) const;

  [[nodiscard]] const glm::vec3& eye() const { return m_eye; }
  [[nodiscard]] const glm::vec3& forward() const { return m_forward; }
  [[nodiscard]] const glm::vec3& right() const { return m_right; }
  [[nodiscard]] const glm::vec3& up() const { return m_up; }

 private:
  glm::vec3 m_eye;
  glm::vec3 m_forward;
  glm::vec3 m_right;
  glm::vec3 m_up;
  float m_tan_half_x;
  /// Inward unit normals of the left, right, bottom and top planes (all through the eye).
  glm::vec3 m_normals[4];
};

// The tests below run for every drop of a million-drop frame: inline.

inline bool ViewFrustum::sphere_visible(const glm::vec3& centre, float radius) const {
  const glm::vec3 rel = centre - m_eye;
  if (glm::dot(rel, m_forward) < -radius) return false;
  for (const auto& normal : m_normals) {
    if (glm::dot(rel, normal) < -radius) return false;
  }
  return true;
}

inline bool ViewFrustum::segment_visible(const glm::vec3& a, const glm::vec3& b,
                                         float margin) const {
  const glm::vec3 ra = a - m_eye;
  const glm::vec3 rb = b - m_eye;
  if (glm::dot(ra, m_forward) < -margin && glm::dot(rb, m_forward) < -margin) return false;
  for (const auto& normal : m_normals) {
    if (glm::dot(ra, normal) < -margin && glm::dot(rb, normal) < -margin) return false;
  }
  return true;
}

inline float ViewFrustum::depth(const glm::vec3& point) const {
  return glm::dot(point - m_eye, m_forward);
}

inline float ViewFrustum::pixel_size(float depth_m, int width_px) const {
  return 2.0f * depth_m * m_tan_half_x / static_cast<float>(width_px);
}

}  // namespace raintrace::povgen
