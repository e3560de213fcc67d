// Splash threshold (Cossali et al. 1997) and crown splash droplets (Bai et al. 2002).
#include "sim/splash.h"

#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "sim/drop_size.h"
#include "sim/terminal_velocity.h"

namespace raintrace::sim {
namespace {

constexpr double kPi = std::numbers::pi;

/// K/K_c computed here from the definitions, independently of splash.cpp.
double k_ratio(double d, double v, double h) {
  const double we = 998.2 * d * v * v / 0.0728;
  const double oh = 1.002e-3 / std::sqrt(998.2 * 0.0728 * d);
  const double k = we * std::pow(oh, -0.4);
  const double delta = std::min(h / d, 1.0);
  return k / (2100.0 + 5880.0 * std::pow(delta, 1.44));
}

ImpactInput impact_of(double d_mm, double water_mm, std::uint64_t key) {
  ImpactInput in;
  in.key = key;
  in.diameter_m = static_cast<float>(d_mm * 1e-3);
  in.velocity = {0.0f, -static_cast<float>(terminal_velocity(d_mm * 1e-3)), 0.0f};
  in.water_depth_m = static_cast<float>(water_mm * 1e-3);
  return in;
}

TEST(Splash, OneMillimetreDropAtTerminalSpeedSitsAtTheThinFilmThreshold) {
  // The numbers: v ≈ 4.0 m/s, We ≈ 220, Oh ≈ 0.0037, K ≈ 2060–2080 ≈ K_c(δ → 0) = 2100.
  const double v = terminal_velocity(1e-3);
  EXPECT_NEAR(v, 4.0, 0.05);
  EXPECT_NEAR(weber_number(1e-3, v), 220.0, 5.0);
  EXPECT_NEAR(ohnesorge_number(1e-3), 0.0037, 0.0001);
  EXPECT_NEAR(splashing_parameter(1e-3, v), 2070.0, 40.0);
  EXPECT_DOUBLE_EQ(critical_splashing_parameter(0.0, 1e-3), 2100.0);
}

TEST(Splash, CriticalParameterGrowsWithFilmDepthAndStopsAtOneDiameter) {
  // Cossali et al.: K_c = 2100 + 5880·δ^1.44; δ = 0.5 → 2100 + 5880·0.3686 = 4267.
  EXPECT_NEAR(critical_splashing_parameter(1e-3, 2e-3), 2100.0 + 5880.0 * std::pow(0.5, 1.44),
              1e-9);
  EXPECT_DOUBLE_EQ(critical_splashing_parameter(2e-3, 2e-3), 7980.0);
  EXPECT_DOUBLE_EQ(critical_splashing_parameter(20e-3, 2e-3), 7980.0);  // deep puddle: δ = 1
}

TEST(Splash, DropsJustBelowTheCriticalDiameterDoNotSplashAndJustAboveDo) {
  for (const double film_mm : {0.0, 0.3, 1.0, 6.0}) {
    const double dc = critical_diameter_at_terminal_speed(film_mm * 1e-3);
    for (const double f : {0.99, 1.01}) {
      const double d = dc * f;
      const double v = terminal_velocity(d);
      const bool expected = k_ratio(d, v, film_mm * 1e-3) > 1.0;
      EXPECT_EQ(expected, f > 1.0) << "film " << film_mm << " mm, D " << d * 1e3 << " mm";
      EXPECT_EQ(splashes(d, v, film_mm * 1e-3), expected)
          << "film " << film_mm << " mm, D " << d * 1e3 << " mm";
    }
  }
}

TEST(Splash, CriticalDiameterIsAboutOneMillimetreOnAFilmAndMoreInAPuddle) {
  // Thin film: K_c → 2100, reached near 1 mm (above). A 0.3 mm film: δ ≈ 0.28 adds ~940.
  // Deep water (δ = 1, K_c = 7980): a terminal-speed drop needs ~1.65 mm.
  EXPECT_NEAR(critical_diameter_at_terminal_speed(0.0) * 1e3, 1.01, 0.03);
  EXPECT_NEAR(critical_diameter_at_terminal_speed(0.3e-3) * 1e3, 1.15, 0.05);
  EXPECT_NEAR(critical_diameter_at_terminal_speed(6e-3) * 1e3, 1.65, 0.05);
}

TEST(Splash, MostGroundHitsOfModerateRainDoNotSplash) {
  // The figure: at 5 mm/h about 65 % of the drops reaching the ground are under 1 mm,
  // below the thin-film threshold, weighting Marshall-Palmer by fall speed (the flux).
  RainParams rain;
  rain.rate_mm_per_h = 5.0;
  const DropSizeModel sizes(rain);
  const double dc = critical_diameter_at_terminal_speed(0.0);
  const int n = 20000;
  int below = 0;
  for (int i = 0; i < n; ++i) below += sizes.sample_in_flux((i + 0.5) / n) < dc ? 1 : 0;
  EXPECT_NEAR(static_cast<double>(below) / n, 0.65, 0.03);
}

TEST(Splash, NoDropletsBelowTheThreshold) {
  const SplashParams params;
  const double dc = critical_diameter_at_terminal_speed(0.3e-3) * 1e3;
  const CrownSplash crown = crown_splash(params, impact_of(0.98 * dc, 0.3, 1), 7);
  EXPECT_EQ(crown.droplets, 0);
  EXPECT_EQ(crown.expected_droplets, 0.0);
}

TEST(Splash, DropletCountFollowsBaiEtAl) {
  // Mean drawn count over many impacts = 5·(K/K_c − 1) (Bai et al. 2002), for drops from just
  // above the threshold to large ones: floor(N + u) has mean N exactly.
  SplashParams params;
  params.droplets = 64;
  for (const double d_mm : {1.4, 2.0, 3.0}) {
    const ImpactInput base = impact_of(d_mm, 0.3, 0);
    const double expected = 5.0 * (k_ratio(base.diameter_m, -base.velocity.y, 0.3e-3) - 1.0);
    double sum = 0.0;
    const int n = 4000;
    for (int k = 0; k < n; ++k) {
      ImpactInput in = base;
      in.key = static_cast<std::uint64_t>(k);
      const CrownSplash crown = crown_splash(params, in, 3);
      EXPECT_NEAR(crown.expected_droplets, expected, 1e-6 * expected);
      sum += crown.droplets;
    }
    // σ of floor(N + u) is at most 0.5: the mean of 4000 is within 0.03.
    EXPECT_NEAR(sum / n, expected, 0.03) << d_mm << " mm";
  }
  // A 2 mm drop throws about twenty (K/K_c ≈ 4.6 on a 0.3 mm film), a 3 mm one about sixty.
  EXPECT_NEAR(crown_splash(params, impact_of(2.0, 0.3, 1), 3).expected_droplets, 18.0, 3.0);
  EXPECT_NEAR(crown_splash(params, impact_of(3.0, 0.3, 1), 3).expected_droplets, 60.0, 8.0);
}

TEST(Splash, DropletsShareTheEnergyBudgetAndLeaveAtTheirAngles) {
  // Bai et al.'s energy: the droplets carry E_k + E_σ,in − E_σ,out − max(0.8·E_k, E_k,c), each
  // leaving at 5°–50° above the ground plus 0.6 of the drop's speed along it. A fifth of the
  // energy in a third of the mass or less, spread ∝ ln²(D/d): the many small droplets leave about
  // as fast as the drop came (the mass-weighted speed is half that); drag stops them within cm.
  SplashParams params;
  params.droplets = 64;
  ImpactInput in = impact_of(2.0, 0.3, 11);
  in.velocity.x = 1.0f;  // wind: 1 m/s along x
  const double e_in = kPi / 12.0 * 998.2 * std::pow(2e-3, 3) * std::pow(in.velocity.y, 2);
  double energy_ratio = 0.0, speed_sum = 0.0;
  int droplets = 0;
  const int impacts = 300;
  for (int k = 0; k < impacts; ++k) {
    in.key = static_cast<std::uint64_t>(k);
    const CrownSplash crown = crown_splash(params, in, 5);
    ASSERT_GT(crown.droplets, 0);
    EXPECT_GT(crown.kinetic_energy_j, 0.0);
    EXPECT_LT(crown.kinetic_energy_j, 0.2 * e_in + 0.0728 * kPi * 4e-6);
    double energy = 0.0;
    for (int i = 0; i < crown.droplets; ++i) {
      const Droplet d = crown_droplet(crown, in, i, 5);
      glm::vec3 own = d.velocity;
      own.x -= 0.6f * in.velocity.x;  // the share of the drop's tangential speed
      const double speed = std::sqrt(own.x * own.x + own.y * own.y + own.z * own.z);
      const double elevation = std::asin(own.y / speed) * 180.0 / kPi;
      EXPECT_GE(elevation, 5.0 - 1e-3);
      EXPECT_LE(elevation, 50.0 + 1e-3);
      EXPECT_GT(d.diameter_m, 0.1 * crown.max_diameter_m * (1.0 - 1e-5));
      EXPECT_LT(d.diameter_m, crown.max_diameter_m * (1.0 + 1e-5));
      const double mass = kPi / 6.0 * 998.2 * std::pow(d.diameter_m, 3);
      energy += 0.5 * mass * speed * speed;
      speed_sum += speed;
      ++droplets;
    }
    energy_ratio += energy * crown.expected_droplets / crown.droplets / crown.kinetic_energy_j;
  }
  // 300 impacts of ~20 droplets: the budget holds on average to a few %.
  EXPECT_NEAR(energy_ratio / impacts, 1.0, 0.05);
  EXPECT_NEAR(speed_sum / droplets / -in.velocity.y, 1.0, 0.2);
}

TEST(Splash, DropletsFlyUpAFewCentimetresAndFallBack) {
  // A 2.5 mm drop on a film: the small fast droplets stop within centimetres, the largest rise
  // ~10–30 cm; all are back on the ground within 0.5 s, and each keeps its id.
  SplashParams params;
  params.droplets = 64;
  params.lifetime_s = 2.0;
  const ImpactInput in = impact_of(2.5, 0.3, 42);
  float highest = 0.0f;
  std::size_t first = 0;
  std::uint64_t first_id = 0;
  for (double age = 0.0; age < 0.6; age += 0.01) {
    Drops out;
    add_splash_droplets(params, in, age, 1.0f, 0.0, 0.02, 9, out);
    if (age == 0.0) {
      first = out.size();
      ASSERT_GT(first, 10u);
      first_id = out.id[0];
    }
    if (age < 0.015) {
      EXPECT_EQ(out.id.empty() ? 0 : out.id[0], first_id);
    }
    for (const glm::vec3& p : out.position) highest = std::max(highest, p.y);
    if (age > 0.5) {
      EXPECT_EQ(out.size(), 0u) << "at " << age << " s";
    }
  }
  EXPECT_GT(highest, 0.005f);
  EXPECT_LT(highest, 0.35f);
}

TEST(Splash, AFlightLookedAtOftenEndsWhereOneLookedAtOnceDoes) {
  // Whole steps from the impact: stopping at frame times on the way changes nothing.
  SplashParams params;
  params.droplets = 64;
  const ImpactInput in = impact_of(3.0, 0.3, 5);
  std::vector<FlyingDroplet> once, often;
  launch_droplets(crown_splash(params, in, 1), in, 0.0, 1.0f, 0.0, 0.02, 1, once);
  often = once;
  for (FlyingDroplet& d : once) fly(d, 0.137);
  for (FlyingDroplet& d : often) {
    for (double t = 0.0; t < 0.137; t += 1.0 / 24.0) fly(d, t);
    fly(d, 0.137);
  }
  ASSERT_EQ(once.size(), often.size());
  for (std::size_t i = 0; i < once.size(); ++i) {
    EXPECT_EQ(once[i].position, often[i].position);
    EXPECT_EQ(once[i].steps, often[i].steps);
  }
}

TEST(Splash, SameImpactSameDroplets) {
  const SplashParams params;
  const ImpactInput in = impact_of(3.0, 0.3, 77);
  Drops a, b;
  add_splash_droplets(params, in, 0.05, 2.0f, 0.0, 0.02, 4, a);
  add_splash_droplets(params, in, 0.05, 2.0f, 0.0, 0.02, 4, b);
  ASSERT_GT(a.size(), 0u);
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(a.position, b.position);
  for (const float o : a.opacity) EXPECT_FLOAT_EQ(o, 2.0f);  // weight 2, not fading yet
}

TEST(Splash, DropletsFainterThanTheFloorAreLeftOut) {
  // A droplet blocks the share (d/pixel)·(d/streak) of its pixels' light. Seen through 2 cm
  // pixels in a still frame (the streak one pixel long), droplets of ~0.3 mm block ~2·10⁻⁴ and
  // are left out; the few of 2 mm or more block over kDropletCoverageFloor and are kept as they
  // are, each one droplet. (Until 2026-12-06 the faint ones were kept by chance, each carrying a
  // whole pixel's light: opaque white dashes on the road.)
  SplashParams params;
  params.droplets = 64;
  const double pixel = 0.02;
  auto share = [&](const Drops& d, std::size_t i) {
    return std::min(1.0, d.diameter[i] / pixel) * d.diameter[i] / pixel;
  };
  std::size_t n_all = 0, n_showing = 0, n_kept = 0, n_wrong = 0;
  for (std::uint64_t key = 0; key < 1000; ++key) {
    const ImpactInput in = impact_of(2.5, 0.3, key);
    Drops a, b;
    add_splash_droplets(params, in, 0.0, 1.0f, 0.0, 0.0, 3, a);
    add_splash_droplets(params, in, 0.0, 1.0f, pixel, 0.0, 3, b);
    n_all += a.size();
    for (std::size_t i = 0; i < a.size(); ++i) n_showing += share(a, i) >= kDropletCoverageFloor;
    n_kept += b.size();
    for (std::size_t i = 0; i < b.size(); ++i) {
      if (share(b, i) < kDropletCoverageFloor || b.opacity[i] != 1.0f) ++n_wrong;
    }
  }
  EXPECT_LT(n_kept * 10, n_all);
  EXPECT_GT(n_kept, 20u);
  EXPECT_EQ(n_kept, n_showing);
  EXPECT_EQ(n_wrong, 0u);
}

}  // namespace
}  // namespace raintrace::sim
