// Ring ripples: speed and spacing of capillary-gravity rings, fading, pixel filtering.
#include "sim/ripples.h"

#include <gtest/gtest.h>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include "sim/splash.h"
#include "sim/terminal_velocity.h"
#include "sim/world.h"

namespace raintrace::sim {
namespace {

/// Radius of the highest crest along +x from the centre, m (0.1 mm steps).
double crest_radius(const Ripple& r) {
  double best = 0.0, best_h = -1.0;
  for (double x = 0.0; x < 0.5; x += 1e-4) {
    const double h = ripple_at(r, r.x + x, r.z).height;
    if (h > best_h) {
      best_h = h;
      best = x;
    }
  }
  return best;
}

TEST(Ripples, RingsAreTheMeasuredOnesAndSpreadAtTheirGroupVelocity) {
  // Raindrop rings measured at a steady 0.2 rad/mm: λ = 31.4 mm. Their packet spreads at the group
  // velocity dω/dk there, (g + 3σk²/ρ)/(2ω) = 0.184 m/s: just above the group velocity's minimum
  // (0.178 m/s at 45 mm), below the phase speed (0.25 m/s).
  EXPECT_NEAR(ripple_wavelength(), 0.0314, 0.0001);
  EXPECT_NEAR(ripple_speed(), 0.184, 0.001);
  // The ring's crest moves out at that speed: 0.1 s apart, 18 mm further.
  const Ripple a = make_ripple({1.0f, 0.0f, 2.0f}, 2e-3f, 0.1, 6e-3, true, 0.5);
  const Ripple b = make_ripple({1.0f, 0.0f, 2.0f}, 2e-3f, 0.2, 6e-3, true, 0.5);
  EXPECT_NEAR(crest_radius(b) - crest_radius(a), 0.0184, 0.001);
  EXPECT_NEAR(crest_radius(a), 0.002 + 0.0184, 0.002);
}

TEST(Ripples, ARingCarriesAboutOnePercentOfTheDropsKineticEnergy) {
  // "The fraction of the incident kinetic energy converted into ring-waves is of the order of
  // 1 %" (2.2 and 2.8 mm drops, IEEE J. Oceanic Eng. 24(3), 1999). A wave's energy is twice its
  // potential and surface energy, ∫∫ ρg·h²/2 + σ·|∇h|²/2 dA, summed here over a snapshot of a
  // 2.8 mm drop's ring 0.2 s old (5 cm out, clear of the centre), with a 5 s lifetime whose
  // fade, (1 − t/T)² on the amplitude, is divided out: the energy it started with. The closed
  // form the amplitude is set by leaves out the envelope's own slope (a few per cent).
  const double d = 2.8e-3, age = 0.2, lifetime = 5.0;
  const Ripple r =
      make_ripple({0.0f, 0.0f, 0.0f}, static_cast<float>(d), age, 6e-3, true, lifetime);
  const double step = 2e-4;
  double energy = 0.0;
  for (double x = -0.12; x < 0.12; x += step) {
    for (double z = -0.12; z < 0.12; z += step) {
      const RippleSample s = ripple_at(r, x, z);
      energy += (kWaterDensity * kGravity * s.height * s.height +
                 kWaterSurfaceTension * (s.slope_x * s.slope_x + s.slope_z * s.slope_z)) *
                step * step;
    }
  }
  energy /= std::pow(1.0 - age / lifetime, 4.0);
  const double mass = kWaterDensity * std::numbers::pi / 6.0 * d * d * d;
  const double kinetic = 0.5 * mass * std::pow(terminal_velocity(d), 2.0);
  EXPECT_NEAR(energy / kinetic, 0.01, 0.0008);
}

TEST(Ripples, PuddleRingsFadeWithinTheirLifetimeAndFilmOnesFaster) {
  const glm::vec3 p{0.0f, 0.0f, 0.0f};
  EXPECT_GT(make_ripple(p, 2e-3f, 0.45, 6e-3, true, 0.5).lifetime_s, 0.0f);
  EXPECT_EQ(make_ripple(p, 2e-3f, 0.5, 6e-3, true, 0.5).lifetime_s, 0.0f);
  // A 0.3 mm film stops the wave within h²/ν ≈ 0.09 s.
  const Ripple film = make_ripple(p, 2e-3f, 0.0, 0.3e-3, false, 0.5);
  EXPECT_NEAR(film.lifetime_s, 0.09, 0.005);
  EXPECT_LE(film.amplitude_m, 0.15e-3f);  // half the film
  // Amplitude falls as the ring spreads and fades: a tenth of a second on, the crest is lower.
  const auto peak = [](const Ripple& r) {
    double h = 0.0;
    for (double x = 0.0; x < 0.3; x += 1e-4) h = std::max(h, ripple_at(r, x, 0.0).height);
    return h;
  };
  EXPECT_GT(peak(make_ripple(p, 2e-3f, 0.05, 6e-3, true, 0.5)),
            2.0 * peak(make_ripple(p, 2e-3f, 0.25, 6e-3, true, 0.5)));
}

TEST(Ripples, SlopeIsTheGradientOfTheHeight) {
  const Ripple r = make_ripple({0.3f, 0.0f, -0.2f}, 2.5e-3f, 0.12, 6e-3, true, 0.5);
  for (const double angle : {0.3, 1.9, 4.0}) {
    for (const double radius : {0.025, 0.03, 0.035}) {
      const double x = r.x + radius * std::cos(angle), z = r.z + radius * std::sin(angle);
      const double e = 1e-6;
      const RippleSample s = ripple_at(r, x, z);
      const double gx = (ripple_at(r, x + e, z).height - ripple_at(r, x - e, z).height) / (2 * e);
      const double gz = (ripple_at(r, x, z + e).height - ripple_at(r, x, z - e).height) / (2 * e);
      EXPECT_NEAR(s.slope_x, gx, 1e-6 + 1e-4 * std::abs(gx));
      EXPECT_NEAR(s.slope_z, gz, 1e-6 + 1e-4 * std::abs(gz));
    }
  }
}

TEST(Ripples, WideningPixelsSmoothTheRingsAway) {
  // Square pixels of 3 mm keep exp(−(2π/λ·0.64·0.003)²/2) = 93 % of a 31 mm ring; of 3 cm
  // (about a pixel a wavelength), nothing visible.
  const Ripple r = make_ripple({0.0f, 0.0f, 0.0f}, 2e-3f, 0.1, 6e-3, true, 0.5);
  const double radius = crest_radius(r);
  const double sharp = ripple_at(r, radius, 0.0).height;
  EXPECT_NEAR(ripple_at(r, radius, 0.0, {0.003, 0.003, 1.0, 0.0}).height / sharp, 0.93, 0.01);
  EXPECT_LT(ripple_at(r, radius, 0.0, {0.03, 0.03, 1.0, 0.0}).height / sharp, 1e-3);
  EXPECT_EQ(ripple_at(r, radius + ripple_reach(r), 0.0).height, 0.0);
}

TEST(Ripples, SlantSmoothsTheRingWhereItRunsAlongTheLineOfSight) {
  // Seen along +x through pixels 3 mm across and 12 mm deep: the ring's crest on the x axis
  // (its wave runs along the line of sight) is smoothed by the 12 mm span to exp(−1.17) ≈ 31 %,
  // the one on the z axis (across) only by the 3 mm one, to 93 %.
  const Ripple r = make_ripple({0.0f, 0.0f, 0.0f}, 2e-3f, 0.1, 6e-3, true, 0.5);
  const double radius = crest_radius(r);
  const PixelSpan span{0.003, 0.012, 1.0, 0.0};
  const double sharp = ripple_at(r, radius, 0.0).height;
  EXPECT_NEAR(ripple_at(r, 0.0, radius, span).height / sharp, 0.93, 0.01);
  EXPECT_NEAR(ripple_at(r, radius, 0.0, span).height / sharp, 0.31, 0.01);
}

TEST(Ripples, RoughnessOfRainedOnWaterMatchesTheClosedForm) {
  // The rings of a simulated 10 mm/h on big puddles, summed at 400 points deep inside them:
  // their mean square slope is ripple_slope_rms()² (within 15 %: the points see a few hundred
  // rings each, and the closed form leaves out the envelope's own slope, +3.5 %, and rings cut
  // short by a puddle's edge).
  SimParams p;
  p.puddles.coverage = 0.9;
  p.puddles.size_m = 20.0;
  // Somewhere deep in a puddle, looked at steeply from 1.5 m (about 2 m² of ground in view).
  const PuddleField field(p.puddles, p.puddles.seed);
  double x0 = 0.0;
  while (field.value(x0, 0.0) < field.threshold() + 1.0) x0 += 0.5;
  p.camera.position = {x0, 1.5, -0.5};
  p.camera.look_at = {x0, 0.0, 0.0};
  p.camera.width_px = 100000;  // every ring drawn, none left to the roughness
  p.rain.far_m = 2.0;
  p.rain.rate_mm_per_h = 10.0;
  p.splashes.enabled = false;
  World world(p);
  world.advance_to(1.0);
  const Frame f = world.snapshot(1);
  // Rings by 5 cm cell, so each point sums only those that can reach it.
  std::map<std::pair<int, int>, std::vector<const Ripple*>> cells;
  auto cell = [](double v) { return static_cast<int>(std::floor(v / 0.05)); };
  for (const Ripple& r : f.ripples) cells[{cell(r.x), cell(r.z)}].push_back(&r);
  double sum = 0.0;
  int points = 0;
  for (int i = 0; i < 20; ++i) {
    for (int j = 0; j < 20; ++j) {
      const double x = x0 - 0.5 + 0.05 * i, z = -0.5 + 0.05 * j;
      if (world.puddles().depth_m(x, z) < 5.9e-3) continue;  // deep inside: full depth
      double sx = 0.0, sz = 0.0;
      for (int a = -4; a <= 4; ++a) {
        for (int b = -4; b <= 4; ++b) {
          const auto it = cells.find({cell(x) + a, cell(z) + b});
          if (it == cells.end()) continue;
          for (const Ripple* r : it->second) {
            const RippleSample s = ripple_at(*r, x, z);
            sx += s.slope_x;
            sz += s.slope_z;
          }
        }
      }
      sum += sx * sx + sz * sz;
      ++points;
    }
  }
  ASSERT_GT(points, 100);
  const double rms = ripple_slope_rms(10.0, 0.5);
  EXPECT_NEAR(std::sqrt(sum / points) / rms, 1.0, 0.15) << points << " points";
}

}  // namespace
}  // namespace raintrace::sim
