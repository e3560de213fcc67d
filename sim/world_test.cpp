// World: validation, prewarm, containment, determinism and thread-count independence.
#include "sim/world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "sim/splash.h"
#include "sim/terminal_velocity.h"

namespace raintrace::sim {
namespace {

// A small view so tests run fast: far 3 m holds a few thousand drops in view, ~30 000 in the
// simulated box; a short prewarm (the fill is already at steady state).
SimParams small_scene() {
  SimParams p;
  p.rain.far_m = 3.0;
  p.rain.rate_mm_per_h = 10.0;
  p.prewarm_s = 0.2;
  p.threads = 1;
  return p;
}

std::string error_of(const SimParams& p) {
  try {
    World w(p);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(World, RejectsFarNotBeyondNearNamingTheField) {
  SimParams p = small_scene();
  p.rain.far_m = 0.2;
  EXPECT_NE(error_of(p).find("rain.far_m must be > rain.near_m"), std::string::npos) << error_of(p);
}

TEST(World, RejectsOutOfRangeFieldsByName) {
  SimParams p = small_scene();
  p.substep_s = 0.5;
  EXPECT_NE(error_of(p).find("substep_s"), std::string::npos);
  p = small_scene();
  p.wind.turbulence_m_per_s = std::nan("");
  EXPECT_NE(error_of(p).find("wind.turbulence_m_per_s"), std::string::npos);
  p = small_scene();
  p.camera.look_at = p.camera.position;
  EXPECT_NE(error_of(p).find("camera.look_at"), std::string::npos);
  p = small_scene();
  p.lightning.generations = 9;
  EXPECT_NE(error_of(p).find("lightning.generations"), std::string::npos);
}

TEST(World, ACancelFlagStopsThePrewarmAndAdvanceBetweenSubsteps) {
  SimParams p = small_scene();
  p.prewarm_s = 60.0;  // 300 000 substeps: never finished if the flag were not checked
  p.substep_s = 2e-4;
  std::atomic<bool> cancel{true};
  EXPECT_THROW(World(p, &cancel), Cancelled);
  p.prewarm_s = 0.0;
  cancel = false;
  World world(p, &cancel);
  world.advance_to(0.01);
  const double t = world.time_s();
  cancel = true;
  EXPECT_THROW(world.advance_to(1e9), Cancelled);  // fps = 1e-9: frame 2 lies at 1e9 s
  EXPECT_LT(world.time_s(), t + 1e-3);             // stopped at the first substep check
}

TEST(World, EstimateMatchesWhatTheWorldHolds) {
  // World::estimate is what budgets are made from: it must be the count the World holds, in
  // still air and in wind, where the fill keeps only the drops that can still reach the view
  // (about half of the box; counted as the whole box until 2026-12-05, twice too many).
  SimParams p = small_scene();
  for (const glm::dvec3 wind : {glm::dvec3{0.0}, glm::dvec3{6.0, 0.0, 2.0}}) {
    p.wind.velocity_m_per_s = wind;
    const WorkEstimate e = World::estimate(p);
    World world(p);
    EXPECT_NEAR(static_cast<double>(world.drops().size()), e.drops, 0.05 * e.drops)
        << "wind " << wind.x;
    world.advance_to(0.5);  // and after the spawned drops have replaced the filled ones
    EXPECT_NEAR(static_cast<double>(world.drops().size()), e.drops, 0.05 * e.drops)
        << "wind " << wind.x;
    const double in_view = static_cast<double>(world.snapshot(1).drops.size());
    EXPECT_NEAR(in_view, e.drops_in_view, 0.1 * e.drops_in_view);
    EXPECT_DOUBLE_EQ(e.prewarm_steps, std::round(p.prewarm_s / p.substep_s));
    EXPECT_DOUBLE_EQ(e.steps_until(1.0, p.substep_s), e.prewarm_steps + 1.0 / p.substep_s);
  }
}

TEST(World, FirstFrameIsAlreadyFullOfRain) {
  const SimParams p = small_scene();
  World world(p);
  EXPECT_DOUBLE_EQ(world.time_s(), 0.0);
  const Frame f = world.snapshot(1);
  // Expected drops in view = density × frustum volume; Poisson-like spread is ~sqrt(n), so
  // 15 % is many standard deviations for the thousands of drops here.
  const double expected = world.sizes().number_density_per_m3() * f.view_volume_m3;
  ASSERT_GT(expected, 300.0);
  EXPECT_NEAR(static_cast<double>(f.drops.size()), expected, 0.15 * expected);
}

TEST(World, DensityInViewStaysConstant) {
  const SimParams p = small_scene();
  World world(p);
  const double expected = world.sizes().number_density_per_m3() * world.view().volume_m3();
  for (int frame = 1; frame <= 8; ++frame) {
    world.advance_to(frame * 0.25);
    const double n = static_cast<double>(world.snapshot(frame).drops.size());
    EXPECT_NEAR(n, expected, 0.15 * expected) << "at t = " << world.time_s();
  }
}

TEST(World, AdvancesInWholeSubsteps) {
  SimParams p = small_scene();
  p.substep_s = 0.004;
  World world(p);
  world.advance_to(0.1);  // 25 substeps exactly
  EXPECT_NEAR(world.time_s(), 0.1, 1e-12);
  world.advance_to(0.103);  // not a whole substep further: stays
  EXPECT_NEAR(world.time_s(), 0.1, 1e-12);
  world.advance_to(0.05);  // the past: no-op
  EXPECT_NEAR(world.time_s(), 0.1, 1e-12);
}

void expect_inside_and_finite(const World& world) {
  const Drops& d = world.drops();
  const SpawnRegion& r = world.region();
  for (std::size_t i = 0; i < d.size(); ++i) {
    const glm::dvec3 p(d.position[i]);
    ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    ASSERT_TRUE(std::isfinite(d.velocity[i].x) && std::isfinite(d.velocity[i].y));
    const double a = r.across(p), b = r.along(p);
    // float positions vs double bounds: allow a micrometre.
    ASSERT_GE(a, r.a0() - 1e-3);
    ASSERT_LE(a, r.a1() + 1e-3);
    ASSERT_GE(b, r.b0() - 1e-3);
    ASSERT_LE(b, r.b1() + 1e-3);
    ASSERT_GT(p.y, r.ground() - 1e-3);
    ASSERT_LE(p.y, r.ceiling() + 1e-3);
  }
}

TEST(World, DropsNeverEscapeOrBecomeNaNInStrongGustyTurbulentWind) {
  SimParams p = small_scene();
  p.wind.velocity_m_per_s = {12.0, 0.0, -6.0};
  p.wind.gusts = true;
  p.wind.gust_strength = 150.0;  // peaks of 15 m/s
  p.wind.turbulence_m_per_s = 6.0;
  p.wind.turbulence_scale_m = 1.0;
  p.substep_s = 0.02;  // the largest substep allowed
  // Few, fast drops keep the wide upwind box cheap.
  p.rain.far_m = 1.5;
  p.rain.rate_mm_per_h = 1.0;
  p.rain.diameter_min_mm = 1.5;
  World world(p);
  for (int k = 1; k <= 20; ++k) {
    world.advance_to(k * 0.1);
    expect_inside_and_finite(world);
  }
  EXPECT_GT(world.drops().size(), 0u);
}

TEST(World, SimulatesOnlyDropsThatCanDriftOntoTheFootprint) {
  SimParams p = small_scene();
  p.wind.velocity_m_per_s = {3.0, 0.0, 0.0};
  World world(p);
  world.advance_to(0.2);
  const SpawnRegion& r = world.region();
  const Drops& d = world.drops();
  std::size_t upwind = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const glm::dvec3 q(d.position[i]);
    // 1 % slack: float positions, and a merged or broken drop's speed differs from v_t.
    EXPECT_TRUE(
        r.reaches_footprint(r.across(q), r.along(q), q.y, 0.99 * terminal_velocity(d.diameter[i])));
    upwind += r.across(q) < r.fa0();
  }
  // The upwind wedge is populated: wind-blown rain enters the view at full density.
  EXPECT_GT(upwind, d.size() / 10);
  // About half the box (the wedge above the extension, thinner for fast drops) is skipped.
  EXPECT_LT(static_cast<double>(d.size()),
            0.8 * world.sizes().number_density_per_m3() * r.volume_m3());
}

bool same_frame(const Frame& a, const Frame& b) {
  // memcmp: bit-identical arrays (the element types have no padding); ripples compare by ==.
  auto same = [](const auto& x, const auto& y) {
    return x.size() == y.size() &&
           (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0);
  };
  return same(a.drops.id, b.drops.id) && same(a.drops.position, b.drops.position) &&
         same(a.drops.velocity, b.drops.velocity) && same(a.drops.diameter, b.drops.diameter) &&
         same(a.drops.acceleration, b.drops.acceleration) && same(a.drops.age, b.drops.age) &&
         same(a.drops.opacity, b.drops.opacity) && same(a.splashes.id, b.splashes.id) &&
         same(a.splashes.position, b.splashes.position) &&
         same(a.splashes.opacity, b.splashes.opacity) && a.ripples == b.ripples &&
         a.flash == b.flash && a.bolts.size() == b.bolts.size();
}

TEST(World, SameSeedGivesIdenticalState) {
  SimParams p = small_scene();
  p.rain.far_m = 2.0;
  p.wind.turbulence_m_per_s = 0.5;
  p.lightning.enabled = true;
  p.lightning.first_strike_s = 0.1;
  World a(p), b(p);
  a.advance_to(0.2);
  b.advance_to(0.2);
  EXPECT_TRUE(same_frame(a.snapshot(1), b.snapshot(1)));
  p.seed = 2;
  World c(p);
  c.advance_to(0.2);
  EXPECT_FALSE(same_frame(a.snapshot(1), c.snapshot(1)));
}

// `raintrace render --frames 16`, a resumed run and a cluster task each take snapshots of only
// some frames: the frames they share with a whole run must be the same, in the same order.
TEST(World, AFrameIsTheSameWhicheverFramesWereTakenBeforeIt) {
  SimParams p = small_scene();
  p.camera.look_at = {0.0, 0.0, 0.0};  // the ground in front: splashes, near and sampled
  World every_frame(p), last_only(p);
  constexpr int kLast = 8;
  Frame whole_run;
  for (int n = 1; n <= kLast; ++n) {
    every_frame.advance_to(n / 24.0);
    whole_run = every_frame.snapshot(n);
  }
  last_only.advance_to(kLast / 24.0);
  const Frame alone = last_only.snapshot(kLast);
  ASSERT_GT(whole_run.splashes.size(), 10u);
  EXPECT_TRUE(same_frame(whole_run, alone));
}

TEST(World, OneAndTwoThreadsGiveBitIdenticalSnapshots) {
  // Big enough (> 32768 drops) that two threads really split the work.
  SimParams p;
  p.rain.far_m = 5.0;
  p.rain.rate_mm_per_h = 20.0;
  // Wind only along the view (no upwind box extension) and gentle turbulence.
  p.camera.look_at = {0.0, 1.6, 5.0};
  p.wind.velocity_m_per_s = {0.0, 0.0, -0.3};
  p.wind.turbulence_m_per_s = 0.3;
  p.prewarm_s = 0.05;
  p.threads = 1;
  World one(p);
  p.threads = 2;
  World two(p);
  ASSERT_GT(one.drops().size(), 40000u);
  one.advance_to(0.1);
  two.advance_to(0.1);
  EXPECT_TRUE(same_frame(one.snapshot(3), two.snapshot(3)));
}

TEST(World, WaterReachingTheGroundMatchesTheRainRate) {
  for (const double rate : {5.0, 30.0}) {
    SimParams p = small_scene();
    p.rain.far_m = 2.0;
    p.rain.rate_mm_per_h = rate;
    p.splashes.enabled = false;  // not needed here; keeps the test fast
    World world(p);
    world.advance_to(3.0);
    const Frame f = world.snapshot(1);
    // depth = volume / area; mm/h = m · 1000 / s · 3600.
    const double measured = f.ground_water_m3 / f.ground_area_m2 * 1000.0 / f.time_s * 3600.0;
    EXPECT_NEAR(measured, rate, 0.1 * rate) << "ground hits " << f.ground_hits;
  }
}

TEST(World, SplashesAndRipplesComeFromRecentImpacts) {
  SimParams p = small_scene();
  p.camera.look_at = {0.0, 0.0, 0.0};  // looking down at the ground in front
  p.puddles.coverage = 0.3;
  World world(p);
  world.advance_to(0.5);
  const Frame f = world.snapshot(1);
  ASSERT_GT(f.splash_events, 0.0);
  ASSERT_GT(f.ripple_events, 0.0);
  ASSERT_GT(f.splashes.size(), 0u);
  ASSERT_GT(f.ripples.size(), 0u);
  // Every droplet is above the ground within reach of an impact of the last lifetime_s that
  // splashed (mid-sized droplets of big drops fly up to ~1 m).
  std::vector<const GroundImpact*> splashed;
  for (const GroundImpact& i : world.ground_impacts()) {
    const double age = f.time_s - i.time_s;
    if (age >= 0.0 && age < p.splashes.lifetime_s &&
        splashes(i.diameter_m, -i.velocity.y, i.water_depth_m)) {
      splashed.push_back(&i);
    }
  }
  for (std::size_t k = 0; k < f.splashes.size(); ++k) {
    const glm::vec3 d = f.splashes.position[k];
    EXPECT_GE(d.y, 0.0f);
    EXPECT_GT(f.splashes.opacity[k], 0.0f);
    bool near = false;
    for (const GroundImpact* i : splashed) {
      near = near || std::hypot(d.x - i->position.x, d.z - i->position.z) < 1.5;
    }
    EXPECT_TRUE(near) << "droplet " << k << " at " << d.x << ", " << d.y << ", " << d.z;
  }
  // Ripples sit on impacts: a puddle's rings, or a film's short ones.
  for (const Ripple& r : f.ripples) {
    bool found = false;
    for (const GroundImpact& i : world.ground_impacts()) {
      found = found || (i.position.x == r.x && i.position.z == r.z &&
                        std::abs(f.time_s - i.time_s - r.age_s) < 1e-4);
    }
    EXPECT_TRUE(found);
    EXPECT_LT(r.age_s, r.lifetime_s);
  }
}

TEST(World, AFallingDropLandsWhereItLandsOnce) {
  // Drops of the volume about to land inside its footprint become impacts keyed by their id at
  // their landing point, and no sampled impact lands inside the footprint while they do.
  SimParams p = small_scene();
  p.camera.look_at = {0.0, 0.0, 0.0};
  p.camera.width_px = 100000;  // every impact kept by the level of detail
  World world(p);
  world.advance_to(0.1);
  struct Landing {
    std::uint64_t id;
    glm::vec3 position;
  };
  std::vector<Landing> landing;
  const Drops& d = world.drops();
  for (std::size_t i = 0; i < d.size(); ++i) {
    // 1 cm above the ground and falling: lands within the next substeps.
    const glm::dvec3 ahead = glm::dvec3(d.position[i]) +
                             glm::dvec3(d.velocity[i]) * double(d.position[i].y / -d.velocity[i].y);
    if (d.position[i].y < 0.01f && world.region().in_measure_area({ahead.x, 0.0, ahead.z})) {
      landing.push_back({d.id[i], glm::vec3(ahead)});
    }
  }
  ASSERT_GT(landing.size(), 10u);
  world.advance_to(0.12);
  for (const Landing& l : landing) {
    int found = 0;
    for (const GroundImpact& i : world.ground_impacts()) {
      if (i.key != l.id) continue;
      ++found;
      EXPECT_NEAR(i.position.x, l.position.x, 2e-3f);
      EXPECT_NEAR(i.position.z, l.position.z, 2e-3f);
    }
    EXPECT_EQ(found, 1) << "drop " << l.id;
  }
  // (Before the volume's drops started, the prewarm's beginning, the sampler covers it too.)
  for (const GroundImpact& i : world.ground_impacts()) {
    if ((i.key >> 63) != 0 && i.time_s >= -p.prewarm_s) {
      EXPECT_FALSE(world.region().in_measure_area(glm::dvec3(i.position)));
    }
  }
}

TEST(World, DropsMergeInFlightAndNoneExceedsTheBreakupDiameter) {
  // Heavy rain of large drops: collisions are frequent enough to see in a short run.
  SimParams p = small_scene();
  p.rain.far_m = 2.0;
  p.rain.rate_mm_per_h = 100.0;
  p.rain.diameter_min_mm = 2.0;
  p.splashes.enabled = false;
  World world(p);
  world.advance_to(0.5);
  EXPECT_GT(world.merges(), 0u);
  for (const float d : world.drops().diameter) {
    EXPECT_LE(d, p.rain.breakup_diameter_mm * 1e-3 + 1e-6);
  }
}

/// Largest minus smallest mean horizontal (x) velocity of the drops in view, sampled every
/// 0.1 s over `seconds`.
double drop_sway_m_per_s(const SimParams& p, double seconds) {
  World world(p);
  double lo = 1e9;
  double hi = -1e9;
  for (int n = 0; n <= static_cast<int>(seconds * 10.0); ++n) {
    world.advance_to(0.1 * n);
    const Frame f = world.snapshot(n + 1);
    double vx = 0.0;
    for (const glm::vec3& v : f.drops.velocity) vx += v.x;
    vx /= static_cast<double>(std::max<std::size_t>(f.drops.size(), 1));
    lo = std::min(lo, vx);
    hi = std::max(hi, vx);
  }
  return hi - lo;
}

TEST(World, GustsSwayTheDropsOnlyWhenTheyAreSlowerThanDragCanFollow) {
  // Eq. 5 as printed (a 12.5 Hz flutter of at most ±2 m/s for strength 20) moves the drops'
  // mean by about ±0.1 m/s (a 0.5 mm drop follows a 78.5 rad/s wiggle by 1/(ωτ) ≈ 1/18), because
  // drag lets a drop follow the wind only over its relaxation time v_t/g ≈ 0.2–0.9 s. Stretched to
  // a 20 s period, the same gusts (flutter now 0.8 s, swells of 3–20 s) carry the drops with them:
  // a sway of metres per second.
  SimParams p = small_scene();
  p.rain.far_m = 1.5;
  p.rain.rate_mm_per_h = 5.0;
  p.splashes.enabled = false;
  p.wind.gusts = true;
  p.wind.gust_strength = 20.0;
  p.wind.gust_period_s = 2.0;
  const double printed = drop_sway_m_per_s(p, 4.0);
  p.wind.gust_period_s = 20.0;
  const double stretched = drop_sway_m_per_s(p, 20.0);
  EXPECT_LT(printed, 0.3);
  EXPECT_GT(stretched, 1.0);
  EXPECT_GT(stretched, 5.0 * printed);
}

TEST(World, LightningShowsBoltsAndFlash) {
  SimParams p = small_scene();
  p.rain.far_m = 1.0;
  p.lightning.enabled = true;
  p.lightning.strikes_per_minute = 0.0;
  p.lightning.first_strike_s = 0.1;
  World world(p);
  world.advance_to(0.05);
  EXPECT_TRUE(world.snapshot(1).bolts.empty());
  EXPECT_EQ(world.snapshot(1).flash, 0.0f);
  world.advance_to(0.1);
  const Frame f = world.snapshot(2);
  ASSERT_EQ(f.bolts.size(), 1u);
  EXPECT_EQ(f.lightning_strikes, 1u);
  // The shutter opens at the strike: the frame records the first stroke's decay averaged over
  // the exposure, τ/T·(1 − e^(−T/τ)) with τ = duration / (4·strokes) (later strokes start after
  // the exposure has closed).
  const double tau = p.lightning.flash_duration_s / (4.0 * p.lightning.return_strokes);
  const double exposure = p.camera.exposure_s;
  ASSERT_GT(exposure, 0.0);
  EXPECT_NEAR(f.flash, tau / exposure * (1.0 - std::exp(-exposure / tau)), 1e-6);
  EXPECT_FLOAT_EQ(f.bolts[0].brightness, f.flash);
  EXPECT_FLOAT_EQ(f.bolts[0].branch_brightness, f.flash);  // only the first stroke so far
  EXPECT_GT(f.bolts[0].segments.size(), 10u);
  world.advance_to(0.1 + p.lightning.flash_duration_s + 0.01);
  EXPECT_TRUE(world.snapshot(3).bolts.empty());
}

}  // namespace
}  // namespace raintrace::sim
