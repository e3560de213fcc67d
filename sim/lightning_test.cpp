// Lightning: Fibonacci branching, skeleton geometry, the channel's kinks, flash envelope, Poisson
// schedule.
#include "sim/lightning.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <numbers>
#include <utility>

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

// The kinks: a straight 300 m channel becomes connected pieces of 2–5 m between the same
// ends, whose direction changes from one piece to the next by 16° on average (Hill 1968's
// photogrammetry of channels: ~5 m pieces, mean absolute change 16°), within 3°, over 20
// channels; a channel skimming the ground never dips below it; the same strike kinks the same.
TEST(Lightning, KinksBendTheChannelEveryFewMetresBySixteenDegreesOnAverage) {
  BoltSkeleton straight;
  for (int i = 0; i < 20; ++i) {
    BoltBranch b;
    b.generation = i % 3;
    b.parent = i == 0 ? -1 : 0;
    b.segments.push_back({glm::vec3(10.0f * float(i), 300, 0), glm::vec3(10.0f * float(i), 0, 0),
                          0.5f, b.generation});
    straight.branches.push_back(b);
  }
  const BoltSkeleton kinked = with_kinks(straight, 0.0, 7, 2);
  ASSERT_EQ(kinked.branches.size(), straight.branches.size());
  double turns = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < kinked.branches.size(); ++i) {
    const auto& segs = kinked.branches[i].segments;
    EXPECT_EQ(kinked.branches[i].generation, straight.branches[i].generation);
    EXPECT_EQ(kinked.branches[i].parent, straight.branches[i].parent);
    // 300 m halved six times is 4.7 m, but the bends lengthen the halves: some split a 7th time.
    EXPECT_GE(segs.size(), 64u);
    EXPECT_LE(segs.size(), 128u);
    EXPECT_EQ(segs.front().start, straight.branches[i].segments.front().start);
    EXPECT_EQ(segs.back().end, straight.branches[i].segments.front().end);
    for (std::size_t k = 0; k < segs.size(); ++k) {
      EXPECT_LE(glm::length(segs[k].end - segs[k].start), kKinkSpacingM + 1e-4);
      EXPECT_GT(glm::length(segs[k].end - segs[k].start), 0.4 * kKinkSpacingM);
      EXPECT_EQ(segs[k].radius, 0.5f);
      EXPECT_GE(segs[k].end.y, 0.0f);
      if (k + 1 == segs.size()) continue;
      EXPECT_EQ(segs[k].end, segs[k + 1].start);
      const glm::dvec3 d0 = glm::normalize(glm::dvec3(segs[k].end - segs[k].start));
      const glm::dvec3 d1 = glm::normalize(glm::dvec3(segs[k + 1].end - segs[k + 1].start));
      turns += std::acos(std::clamp(glm::dot(d0, d1), -1.0, 1.0)) * 180.0 / std::numbers::pi;
      ++count;
    }
  }
  const double mean_turn = turns / count;
  std::printf("mean change of direction between pieces: %.1f deg over %d joints\n", mean_turn,
              count);
  EXPECT_NEAR(mean_turn, 16.0, 3.0);
  // A horizontal channel along the ground keeps above it.
  BoltSkeleton low;
  low.branches.push_back({0, -1, {{glm::vec3(0, 0, 0), glm::vec3(100, 0, 0), 0.5f, 0}}});
  const BoltSkeleton low_kinked = with_kinks(low, 0.0, 7, 2);
  ASSERT_GT(low_kinked.branches.front().segments.size(), 16u);
  for (const auto& s : low_kinked.branches.front().segments) {
    EXPECT_GE(s.start.y, 0.0f);
  }
  const BoltSkeleton again = with_kinks(straight, 0.0, 7, 2);
  EXPECT_EQ(again.branches[3].segments[17].end, kinked.branches[3].segments[17].end);
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
    // Strokes add; each has decayed below e^−3 when the next starts: 1 + e^−3 + e^−6 + … .
    EXPECT_LE(b, 1.0 / (1.0 - std::exp(-3.0)));
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

TEST(Lightning, BranchesAreFainterThanTheTrunkAndEachGenerationFainterStill) {
  EXPECT_EQ(branch_brightness(0), 1.0);
  EXPECT_DOUBLE_EQ(branch_brightness(1), 0.35);
  for (int g = 1; g < 8; ++g)
    EXPECT_DOUBLE_EQ(branch_brightness(g + 1), 0.5 * branch_brightness(g));
}

// One stroke (return_strokes = 1): b(t) = e^(−t/τ) on [0, D], τ = D/4. Its averages over a
// shutter have closed forms to test against.
TEST(Lightning, ExposureOfOneStrokeMatchesTheAnalyticIntegral) {
  LightningParams p;
  p.return_strokes = 1;
  p.flash_duration_s = 0.4;
  const double tau = 0.1;
  for (const double t : {0.001, 0.02, 1.0 / 48.0, 0.1}) {
    // Shutter opening at the strike: (1/T) ∫₀ᵀ e^(−t/τ) dt = τ/T · (1 − e^(−T/τ)).
    EXPECT_NEAR(flash_exposure(p, 0.0, t, 1, 0).all_strokes, tau / t * (1.0 - std::exp(-t / tau)),
                1e-12)
        << "T = " << t;
    // Opening before the strike: the dark part of the exposure counts too.
    EXPECT_NEAR(flash_exposure(p, -t / 2, t, 1, 0).all_strokes,
                tau / t * (1.0 - std::exp(-t / 2 / tau)), 1e-12);
    // Straddling the end of the flash: only up to D = 0.4 s.
    EXPECT_NEAR(flash_exposure(p, 0.4 - t / 2, t, 1, 0).all_strokes,
                tau / t * (std::exp(-(0.4 - t / 2) / tau) - std::exp(-4.0)), 1e-12);
  }
  EXPECT_EQ(flash_exposure(p, 0.5, 0.02, 1, 0).all_strokes, 0.0);
  EXPECT_EQ(flash_exposure(p, -0.05, 0.02, 1, 0).all_strokes, 0.0);
}

// Several strokes: the average equals a fine numerical integral of flash_envelope over the
// shutter, wherever the shutter falls (across stroke starts and the end of the flash). Midpoint
// rule with n steps: the envelope jumps by at most ~1 at a stroke's start, which costs at most
// 1/n of the average; smooth parts are far more accurate.
TEST(Lightning, ExposureIsTheEnvelopeAveragedOverTheShutter) {
  LightningParams p;
  p.return_strokes = 4;
  p.flash_duration_s = 0.35;
  const int n = 200000;
  for (const double exposure : {1.0 / 48.0, 0.05}) {
    for (double open = -0.03; open < 0.37; open += 0.0173) {
      double sum = 0.0;
      for (int k = 0; k < n; ++k) {
        sum += flash_envelope(p, open + (k + 0.5) * exposure / n, 7, 2);
      }
      EXPECT_NEAR(flash_exposure(p, open, exposure, 7, 2).all_strokes, sum / n, 2.0 / n)
          << "shutter opens " << open << " s after the strike, exposure " << exposure << " s";
    }
  }
  // A zero exposure records the envelope itself.
  for (double t = 0.0; t < 0.36; t += 0.01) {
    EXPECT_EQ(flash_exposure(p, t, 0.0, 7, 2).all_strokes, flash_envelope(p, t, 7, 2));
  }
}

// Later strokes retrace the main channel only: the branches' light is the first stroke's.
TEST(Lightning, LaterStrokesDoNotLightTheBranches) {
  LightningParams p;
  p.return_strokes = 3;
  p.flash_duration_s = 0.3;
  const FlashExposure early = flash_exposure(p, 0.0, 0.01, 3, 1);
  EXPECT_DOUBLE_EQ(early.first_stroke, early.all_strokes);  // before the second stroke
  // After the second stroke starts (slot 0.1 s ± 0.0125 s) the channel outshines the branches.
  const FlashExposure later = flash_exposure(p, 0.115, 0.01, 3, 1);
  EXPECT_GT(later.all_strokes, 5.0 * later.first_stroke);
}

// Bearing of where a bolt reaches the ground, seen from the camera, in degrees from the view
// direction (positive to the right), and its horizontal distance.
std::pair<double, double> landing(const BoltSkeleton& bolt, const Camera& camera) {
  const glm::dvec3 end(bolt.branches.front().segments.back().end);
  const glm::dvec3 to = end - camera.position;
  const glm::dvec3 fwd = camera.look_at - camera.position;
  const double bearing =
      (std::atan2(to.x, to.z) - std::atan2(fwd.x, fwd.z)) * 180.0 / std::numbers::pi;
  return {std::remainder(bearing, 360.0), std::hypot(to.x, to.z)};
}

TEST(Lightning, FirstStrikeLandsInViewByDefault) {
  LightningParams p;
  Camera camera;  // 60° horizontal field of view
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    p.first_strike_s = 0.5;
    const auto [forced, d0] = landing(build_bolt(p, camera, 0.0, seed, 0), camera);
    p.first_strike_s = -1.0;  // no forced strike: the first random one opens the clip
    const auto [random, d1] = landing(build_bolt(p, camera, 0.0, seed, 1), camera);
    // The trunk steers for its landing point, jittered: within 2 % of the distance.
    EXPECT_LT(std::abs(forced), 0.02 * 180.0 / std::numbers::pi);
    EXPECT_LT(std::abs(random), 0.02 * 180.0 / std::numbers::pi);
    EXPECT_NEAR(d0, p.distance_m, 0.02 * p.distance_m);
    EXPECT_NEAR(d1, p.distance_m, 0.02 * p.distance_m);
  }
}

TEST(Lightning, PlacementKeysSteerTheFirstStrikeAndSpreadTheOthers) {
  LightningParams p;
  p.first_strike_s = 0.0;
  p.azimuth_deg = -40.0;
  p.azimuth_spread_deg = 10.0;
  p.distance_m = 900.0;
  p.distance_min_m = 200.0;
  p.distance_max_m = 300.0;
  Camera camera;
  camera.look_at = camera.position + glm::dvec3{1.0, 0.0, 1.0};  // looking 45° to the right
  const auto [bearing, distance] = landing(build_bolt(p, camera, 0.0, 4, 0), camera);
  EXPECT_NEAR(bearing, -40.0, 0.02 * 180.0 / std::numbers::pi);
  EXPECT_NEAR(distance, 900.0, 18.0);
  double lowest = 180.0, highest = -180.0;
  for (std::uint64_t strike = 1; strike <= 200; ++strike) {
    const auto [b, d] = landing(build_bolt(p, camera, 0.0, 4, strike), camera);
    EXPECT_GE(d, 200.0 - 6.0);
    EXPECT_LE(d, 300.0 + 6.0);
    lowest = std::min(lowest, b);
    highest = std::max(highest, b);
  }
  // 200 uniform draws in [−50°, −30°] come within 1° of both ends (chance to miss one: 0.95²⁰⁰).
  EXPECT_GT(lowest, -50.0 - 2.0);
  EXPECT_LT(lowest, -49.0);
  EXPECT_LT(highest, -30.0 + 2.0);
  EXPECT_GT(highest, -31.0);
}

}  // namespace
}  // namespace raintrace::sim
