// Beard & Chuang axis ratios.
#include "sim/drop_shape.h"

#include <gtest/gtest.h>

namespace raintrace::sim {
namespace {

TEST(DropShape, FollowsBeardChuangPolynomial) {
  // b/a = 1.0048 + 0.0057·D − 2.628·D² + 3.682·D³ − 1.677·D⁴, D in cm:
  // D = 0.2 cm → 1.0048 + 0.00114 − 0.10512 + 0.029456 − 0.0026832 = 0.9275928
  EXPECT_NEAR(axis_ratio(2e-3), 0.9275928, 1e-6);
  // D = 0.35 cm → 0.8175653; D = 0.4 cm → 0.7793168 (the published ≈ 0.8 at 3.5–4 mm).
  EXPECT_NEAR(axis_ratio(3.5e-3), 0.8175653, 1e-6);
  EXPECT_NEAR(axis_ratio(4e-3), 0.7793168, 1e-6);
}

TEST(DropShape, SmallDropsAreSpheres) {
  EXPECT_DOUBLE_EQ(axis_ratio(0.1e-3), 1.0);
  EXPECT_DOUBLE_EQ(axis_ratio(0.0), 1.0);
}

TEST(DropShape, FlattensMonotonicallyWithSize) {
  double previous = 1.0;
  for (double d = 0.5e-3; d <= 8e-3; d += 0.1e-3) {
    EXPECT_LE(axis_ratio(d), previous + 1e-12) << d;
    previous = axis_ratio(d);
  }
  EXPECT_GT(previous, 0.3);
}

}  // namespace
}  // namespace raintrace::sim
