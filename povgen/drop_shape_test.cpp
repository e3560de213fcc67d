// Beard-Chuang axis ratios and the paper's streak length against hand-computed values.
#include "povgen/drop_shape.h"

#include <gtest/gtest.h>

namespace raintrace::povgen {
namespace {

TEST(DropShape, AxisRatioFollowsBeardChuang) {
  // b/a = 1.0048 + 0.0057·D − 2.628·D² + 3.682·D³ − 1.677·D⁴, D in cm:
  // D = 0.1 cm: 1.0048 + 0.00057 − 0.02628 + 0.003682 − 0.0001677 = 0.9826043
  EXPECT_NEAR(drop_axis_ratio(1e-3), 0.9826043, 1e-6);
  // D = 0.5 cm: 1.0048 + 0.00285 − 0.657 + 0.46025 − 0.1048125 = 0.7060875
  EXPECT_NEAR(drop_axis_ratio(5e-3), 0.7060875, 1e-6);
  // Flattening grows with size.
  EXPECT_GT(drop_axis_ratio(2e-3), drop_axis_ratio(4e-3));
}

TEST(DropShape, AxisRatioIsClampedToRoundAndHalf) {
  EXPECT_DOUBLE_EQ(drop_axis_ratio(1e-5), 1.0);   // the fit exceeds 1 for tiny drops
  EXPECT_DOUBLE_EQ(drop_axis_ratio(20e-3), 0.5);  // far past break-up
}

TEST(DropShape, StreakLengthIsPaperEquationThree) {
  // L = V0·t + a·t²/2 + 2R: 9·0.02 + 9.81·0.0004/2 + 2·0.001 = 0.18 + 0.001962 + 0.002
  EXPECT_NEAR(streak_length(9.0, 9.81, 0.02, 0.001), 0.183962, 1e-12);
  // No exposure: just the drop.
  EXPECT_DOUBLE_EQ(streak_length(9.0, 0.0, 0.0, 0.001), 0.002);
  // Strong deceleration never makes the streak shorter than the drop.
  EXPECT_DOUBLE_EQ(streak_length(0.1, -1000.0, 0.02, 0.001), 0.002);
}

}  // namespace
}  // namespace raintrace::povgen
