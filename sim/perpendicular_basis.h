// Two unit vectors at right angles to a direction and to each other: the plane a random
// sideways offset or a transverse wave lies in (the bolt's kinks, the turbulence's modes).
#pragma once

#include <cmath>

#include <glm/glm.hpp>

namespace raintrace::sim {

struct PerpendicularBasis {
  glm::dvec3 u;  ///< ⟂ the direction
  glm::dvec3 v;  ///< ⟂ the direction and u; (direction, u, v) is right-handed
};

/// The plane across unit vector `direction`. Which pair in that plane comes out matters only in
/// that it is fixed: the same direction always gives the same u and v, so seeded offsets built
/// on them repeat exactly. A helper axis not near `direction` keeps the cross product well
/// conditioned: +y, or +x when `direction` is within ~26° of vertical.
inline PerpendicularBasis perpendicular_basis(const glm::dvec3& direction) {
  const glm::dvec3 helper = std::abs(direction.y) < 0.9 ? glm::dvec3{0, 1, 0} : glm::dvec3{1, 0, 0};
  const glm::dvec3 u = glm::normalize(glm::cross(direction, helper));
  return {u, glm::cross(direction, u)};
}

}  // namespace raintrace::sim
