// Paper eq. 3.
#include "sim/streak.h"

#include <gtest/gtest.h>

namespace raintrace::sim {
namespace {

TEST(Streak, LengthIsTravelDuringExposurePlusDiameter) {
  // 9 m/s for 20 ms = 0.18 m, plus 2R = 2 mm.
  EXPECT_NEAR(streak_length(9.0, 0.0, 0.02, 2e-3), 0.182, 1e-12);
  // Accelerating at g: + 9.80665·0.02²/2 = 0.00196133 m.
  EXPECT_NEAR(streak_length(9.0, 9.80665, 0.02, 2e-3), 0.182 + 0.00196133, 1e-12);
}

TEST(Streak, ZeroExposureShowsTheDropItself) {
  EXPECT_DOUBLE_EQ(streak_length(9.0, 3.0, 0.0, 3e-3), 3e-3);
}

TEST(Streak, NeverShorterThanTheDrop) {
  EXPECT_DOUBLE_EQ(streak_length(0.1, -100.0, 0.1, 1e-3), 1e-3);
}

}  // namespace
}  // namespace raintrace::sim
