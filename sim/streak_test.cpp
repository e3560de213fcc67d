// Paper eq. 3.
#include "sim/streak.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

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

/// ∫∫ streak_time_coverage over the streak's rectangle (midpoint rule), m².
double integrated_coverage(double travel, double diameter) {
  const int n_along = 4000;
  const int n_across = 400;
  const double length = travel + diameter;
  const double da = length / n_along;
  const double dx = diameter / n_across;
  double sum = 0.0;
  for (int i = 0; i < n_along; ++i) {
    for (int j = 0; j < n_across; ++j) {
      sum +=
          streak_time_coverage((i + 0.5) * da, -0.5 * diameter + (j + 0.5) * dx, travel, diameter);
    }
  }
  return sum * da * dx;
}

TEST(Streak, CoverageIntegratesToTheDropsAreaWhateverTheExposure) {
  // Garg & Nayar: the exposure spreads a drop's light along its path, it adds none. A 2 mm
  // drop's disc is π·1² = 3.1416 mm², for no motion, half a diameter, and 8 cm (4 m/s, 20 ms).
  const double area = std::numbers::pi * 1e-6;
  for (const double travel : {0.0, 1e-3, 0.08}) {
    EXPECT_NEAR(integrated_coverage(travel, 2e-3), area, 0.003 * area) << travel;
  }
}

TEST(Streak, OpacityIsDiameterOverTravelInTheMiddleAndRampsAtTheEnds) {
  // 1 mm drop moving 8 cm: the middle is covered 1/80 of the time.
  EXPECT_NEAR(streak_time_coverage(0.04, 0.0, 0.08, 1e-3), 1.0 / 80.0, 1e-12);
  EXPECT_NEAR(streak_opacity(0.08, 1e-3), 1.0 / 80.0, 1e-12);
  // Half way up the first ramp (one diameter long) half as much.
  EXPECT_NEAR(streak_time_coverage(0.5e-3, 0.0, 0.08, 1e-3), 0.5 / 80.0, 1e-12);
  // Off the axis the chord is shorter: at 0.4 mm of 0.5 mm, 0.6 of the diameter.
  EXPECT_NEAR(streak_time_coverage(0.04, 0.4e-3, 0.08, 1e-3), 0.6 / 80.0, 1e-12);
  EXPECT_EQ(streak_time_coverage(0.04, 0.6e-3, 0.08, 1e-3), 0.0);
  // A drop moving less than its size is fully covered where it stays all the time.
  EXPECT_DOUBLE_EQ(streak_time_coverage(1e-3, 0.0, 0.5e-3, 2e-3), 1.0);
  EXPECT_DOUBLE_EQ(streak_opacity(0.5e-3, 2e-3), 1.0);
  // No motion: the drop itself, a disc.
  EXPECT_DOUBLE_EQ(streak_time_coverage(1e-3, 0.0, 0.0, 2e-3), 1.0);
  EXPECT_DOUBLE_EQ(streak_time_coverage(1.9e-3, 0.9e-3, 0.0, 2e-3), 0.0);
}

TEST(Streak, DoublingTheExposureDoublesTheLengthAndHalvesTheOpacity) {
  const double d = 1e-3;
  const double l1 = streak_length(4.0, 0.0, 0.02, d);
  const double l2 = streak_length(4.0, 0.0, 0.04, d);
  EXPECT_NEAR(l2 - d, 2.0 * (l1 - d), 1e-12);
  EXPECT_NEAR(streak_opacity(streak_travel(4.0, 0.0, 0.04), d),
              0.5 * streak_opacity(streak_travel(4.0, 0.0, 0.02), d), 1e-12);
}

}  // namespace
}  // namespace raintrace::sim
