// Lightning: Fibonacci branching, skeleton geometry, flash envelope, Poisson schedule.
#include "sim/lightning.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

namespace raintrace::sim {
namespace {

TEST(Lightning, BranchCountsAreFibonacci) {
  const std::vector<int> expected{1, 1, 2, 3, 5, 8, 13, 21};
  EXPECT_EQ(fibonacci_branch_counts(8), expected);
}

TEST(Lightning, SkeletonBranchesPerGenerationFollowFibonacci) {
  LightningParams p;
  p.generations = 7;
  const BoltSkeleton bolt = build_bolt(p, Camera{}, 0.0, 1, 3);
  std::vector<int> counts(7, 0);
  for (const auto& b : bolt.branches) ++counts[b.generation];
  EXPECT_EQ(counts, fibonacci_branch_counts(7));
  // Every generation g ≥ 2 obeys count(g) = count(g−1) + count(g−2), and each parent is one
  // generation up, bearing one or two children (the rabbit rule).
  std::vector<int> children(bolt.branches.size(), 0);
  for (const auto& b : bolt.branches) {
    if (b.generation == 0) continue;
    ASSERT_GE(b.parent, 0);
    EXPECT_EQ(bolt.branches[b.parent].generation, b.generation - 1);
    ++children[b.parent];
  }
  for (std::size_t i = 0; i + 1 < bolt.branches.size(); ++i) {
    if (bolt.branches[i].generation < 6) {
      EXPECT_GE(children[i], 1);
      EXPECT_LE(children[i], 2);
    }
  }
}

TEST(Lightning, TrunkRunsFromCloudBaseToGroundInShrinkingConnectedSteps) {
  LightningParams p;
  p.cloud_height_m = 300.0;
  const double ground = -1.0;
  const BoltSkeleton bolt = build_bolt(p, Camera{}, ground, 5, 0);
  const auto& trunk = bolt.branches.front().segments;
  ASSERT_GT(trunk.size(), 5u);
  EXPECT_NEAR(trunk.front().start.y, ground + 300.0, 1e-3);
  EXPECT_NEAR(trunk.back().end.y, ground, 1e-3);
  for (std::size_t k = 0; k + 1 < trunk.size(); ++k) {
    EXPECT_EQ(trunk[k].end, trunk[k + 1].start);
  }
  const auto len = [](const BoltSegment& s) { return glm::length(s.end - s.start); };
  EXPECT_LT(len(trunk[trunk.size() - 2]), len(trunk[0]));
  // Strikes land within the configured distance of the camera.
  const glm::dvec3 cam = Camera{}.position;
  const double dist = std::hypot(trunk.back().end.x - cam.x, trunk.back().end.z - cam.z);
  EXPECT_GE(dist, p.distance_min_m - 0.3 * 300.0);
  EXPECT_LE(dist, p.distance_max_m + 0.3 * 300.0);
}

TEST(Lightning, RadiusHalvesPerGeneration) {
  LightningParams p;
  const BoltSkeleton bolt = build_bolt(p, Camera{}, 0.0, 1, 1);
  for (const auto& b : bolt.branches) {
    for (const auto& s : b.segments) {
      EXPECT_NEAR(s.radius, p.trunk_radius_m * std::pow(0.5, b.generation), 1e-6);
      EXPECT_EQ(s.generation, b.generation);
    }
  }
}

TEST(Lightning, SameStrikeSameBolt) {
  LightningParams p;
  const auto a = build_bolt(p, Camera{}, 0.0, 9, 4), b = build_bolt(p, Camera{}, 0.0, 9, 4);
  ASSERT_EQ(a.branches.size(), b.branches.size());
  EXPECT_EQ(a.branches.back().segments.back().end, b.branches.back().segments.back().end);
  const auto c = build_bolt(p, Camera{}, 0.0, 9, 5);
  EXPECT_NE(a.branches.front().segments.back().end, c.branches.front().segments.back().end);
}

TEST(Lightning, FlashHasOnePeakPerReturnStroke) {
  LightningParams p;
  p.return_strokes = 4;
  p.flash_duration_s = 0.4;
  EXPECT_EQ(flash_envelope(p, -0.01, 1, 0), 0.0);
  EXPECT_EQ(flash_envelope(p, 0.41, 1, 0), 0.0);
  EXPECT_DOUBLE_EQ(flash_envelope(p, 0.0, 1, 0), 1.0);
  int rises = 0;
  double previous = flash_envelope(p, 0.0, 1, 0);
  for (double t = 1e-4; t <= 0.4; t += 1e-4) {
    const double b = flash_envelope(p, t, 1, 0);
    EXPECT_GE(b, 0.0);
    EXPECT_LE(b, 1.0);
    if (b > previous + 1e-9) ++rises;
    previous = b;
  }
  // Strokes 2..4 each start with a jump up (a rise within one sample).
  EXPECT_EQ(rises, 3);
}

TEST(Lightning, StrikesArriveAtTheConfiguredMeanRate) {
  LightningParams p;
  p.enabled = true;
  p.strikes_per_minute = 60.0;  // 1 per second
  LightningSchedule schedule(p, 3);
  const auto strikes = schedule.strikes_until(2000.0);
  // Poisson: 2000 ± 45 (σ = √2000); 4σ bounds.
  EXPECT_NEAR(static_cast<double>(strikes.size()), 2000.0, 180.0);
  for (std::size_t k = 1; k < strikes.size(); ++k) {
    EXPECT_LE(strikes[k - 1].time_s, strikes[k].time_s);
  }
}

TEST(Lightning, ForcedFirstStrike) {
  LightningParams p;
  p.enabled = true;
  p.strikes_per_minute = 0.0;
  p.first_strike_s = 0.5;
  LightningSchedule schedule(p, 3);
  EXPECT_TRUE(schedule.strikes_until(0.49).empty());
  const auto s = schedule.strikes_until(0.5);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].id, 0u);
  EXPECT_DOUBLE_EQ(s[0].time_s, 0.5);
}

}  // namespace
}  // namespace raintrace::sim
