// The rain drawn around lamps beyond far_m: where its drops are, how dense, which lamps.
#include "sim/lamp_rain.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "sim/random.h"

namespace raintrace::sim {
namespace {

// A lamp 17 m ahead, a little right and above the view's middle.
const glm::dvec3 kLens{1.0, 3.0, 12.0};
constexpr double kReach = 2.0;

// The default camera (eye 1.6 m up at z = −5, looking along +z), rain drawn to 3 m, the lamp
// above, a ball of 2 m around it, lamps to 30 m.
SimParams scene() {
  SimParams p;
  p.lamps = {kLens};
  p.rain.lamp_reach_m = kReach;
  p.rain.lamp_far_m = 30.0;
  p.rain.far_m = 3.0;
  p.rain.rate_mm_per_h = 10.0;
  p.prewarm_s = 0.2;
  p.threads = 1;
  return p;
}

glm::dvec3 centre_for(const glm::dvec3& lens, const glm::dvec3& eye) {
  glm::dvec3 toward = eye - lens;
  toward.y = 0.0;
  return lens + glm::normalize(toward) * (0.5 * kReach) - glm::dvec3{0.0, 0.5 * kReach, 0.0};
}

TEST(LampRain, KeepsItsDropsInTheBallBeyondTheDrawnRainAndInView) {
  const SimParams p = scene();
  LampRain rain(p);
  ASSERT_EQ(rain.lamp_count(), 1u);
  rain.advance_to(0.1);
  Drops drops;
  rain.add_drops(drops);
  ASSERT_GT(drops.size(), 100u);
  const ViewVolume beyond(p.camera, p.rain.far_m, 1000.0);
  const glm::dvec3 centre = centre_for(kLens, p.camera.position);
  for (std::size_t i = 0; i < drops.size(); ++i) {
    const glm::dvec3 at{drops.position[i]};
    EXPECT_LE(glm::length(at - centre), kReach + 1e-4) << i;
    EXPECT_TRUE(beyond.contains(at)) << i;
    EXPECT_GE(drops.id[i], LampRain::kIdStride) << "ids apart from the main World's";
  }
}

TEST(LampRain, HoldsTheRainsDensityInItsBall) {
  const SimParams p = scene();
  LampRain rain(p);
  const World main(p);
  rain.advance_to(0.25);
  Drops drops;
  rain.add_drops(drops);
  // The ball's volume inside the view beyond far_m, by counting points of a lattice-free
  // sample (the same counter-based randomness as the simulation).
  const ViewVolume beyond(p.camera, p.rain.far_m, 1000.0);
  const glm::dvec3 centre = centre_for(kLens, p.camera.position);
  int inside = 0;
  constexpr int kSamples = 400000;
  for (int s = 0; s < kSamples; ++s) {
    const glm::dvec3 u{uniform(99, Stream::fill, s, 0), uniform(99, Stream::fill, s, 1),
                       uniform(99, Stream::fill, s, 2)};
    const glm::dvec3 at = centre + (2.0 * u - 1.0) * kReach;
    if (glm::length(at - centre) <= kReach && beyond.contains(at) && at.y > p.ground_y_m) {
      ++inside;
    }
  }
  const double volume = 8.0 * kReach * kReach * kReach * inside / kSamples;
  ASSERT_GT(volume, 10.0);
  const double expected = main.sizes().number_density_per_m3() * volume;
  // Thousands of drops: 10 % is many standard deviations.
  EXPECT_NEAR(static_cast<double>(drops.size()), expected, 0.1 * expected);
}

TEST(LampRain, LeavesOutLampsOutOfViewTooFarOrBeforeTheDrawnRainsEnd) {
  SimParams p = scene();
  const glm::dvec3 behind{0.0, 3.0, -12.0};
  const glm::dvec3 aside{40.0, 3.0, 0.0};
  const glm::dvec3 beyond_limit{0.0, 3.0, 40.0};
  const glm::dvec3 within_far{0.0, 1.6, -3.0};
  p.lamps = {behind, aside, beyond_limit, within_far};
  EXPECT_EQ(LampRain(p).lamp_count(), 0u);
  EXPECT_EQ(LampRain::estimate(p).drops, 0.0);
  p.lamps = {kLens};
  p.rain.lamp_reach_m = 0.0;
  EXPECT_EQ(LampRain(p).lamp_count(), 0u);
  p.rain.lamp_reach_m = kReach;
  p.rain.lamp_far_m = 10.0;
  EXPECT_EQ(LampRain(p).lamp_count(), 0u);
}

TEST(LampRain, EstimateMatchesWhatItsWorldsHold) {
  const SimParams p = scene();
  const LampRain rain(p);
  const WorkEstimate estimate = LampRain::estimate(p);
  EXPECT_NEAR(static_cast<double>(rain.simulated_drops()), estimate.drops, 0.05 * estimate.drops);
}

TEST(LampRain, TheSameSceneGivesTheSameDropsOnAnyThreadCount) {
  SimParams p = scene();
  p.lamps = {kLens, {-1.0, 3.0, 18.0}};
  LampRain one(p);
  p.threads = 2;
  LampRain two(p);
  ASSERT_EQ(one.lamp_count(), 2u);
  one.advance_to(0.1);
  two.advance_to(0.1);
  Drops a, b;
  one.add_drops(a);
  two.add_drops(b);
  ASSERT_GT(a.size(), 100u);
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.diameter, b.diameter);
}

}  // namespace
}  // namespace raintrace::sim
