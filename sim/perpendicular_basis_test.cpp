// The plane across a direction.
#include "sim/perpendicular_basis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace raintrace::sim {
namespace {

void expect_right_handed_orthonormal(const glm::dvec3& d) {
  const PerpendicularBasis b = perpendicular_basis(d);
  EXPECT_NEAR(glm::length(b.u), 1.0, 1e-12);
  EXPECT_NEAR(glm::length(b.v), 1.0, 1e-12);
  EXPECT_NEAR(glm::dot(b.u, d), 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(b.v, d), 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(b.u, b.v), 0.0, 1e-12);
  // (d, u, v) right-handed: u × v = d.
  EXPECT_NEAR(glm::length(glm::cross(b.u, b.v) - d), 0.0, 1e-12);
}

TEST(PerpendicularBasis, IsOrthonormalAndRightHandedForEveryDirection) {
  // A spiral over the sphere, poles included: straight up and down (a bolt's trunk) take the
  // other helper axis, where crossing with +y would give a zero vector.
  expect_right_handed_orthonormal({0, 1, 0});
  expect_right_handed_orthonormal({0, -1, 0});
  const int n = 400;
  for (int k = 0; k < n; ++k) {
    const double y = 1.0 - 2.0 * (k + 0.5) / n;
    const double r = std::sqrt(1.0 - y * y);
    const double a = k * std::numbers::pi * (3.0 - std::sqrt(5.0));
    expect_right_handed_orthonormal({r * std::cos(a), y, r * std::sin(a)});
  }
}

}  // namespace
}  // namespace raintrace::sim
