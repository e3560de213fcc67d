// A water drop's geometric-optics scattering against known optics: the rainbows, the
// asymmetry parameter of large water spheres, and the fit of POV-Ray's lobes.
#include "sim/drop_optics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace raintrace::sim {
namespace {

const DropScattering& water() {
  static const DropScattering s = drop_scattering();
  return s;
}

double phase_at_degree(int degree) { return water().phase[static_cast<std::size_t>(degree)]; }

TEST(DropOptics, PhaseFunctionIsNormalisedOverTheSphere) {
  double sum = 0.0;
  for (int k = 0; k < 180; ++k) {
    const double lo = k * std::numbers::pi / 180.0;
    const double hi = (k + 1) * std::numbers::pi / 180.0;
    sum += phase_at_degree(k) * 2.0 * std::numbers::pi * (std::cos(lo) - std::cos(hi));
  }
  EXPECT_NEAR(sum / (4.0 * std::numbers::pi), 1.0, 1e-9);
}

TEST(DropOptics, PrimaryRainbowSitsAtDescartesMinimumDeviation) {
  // Descartes: cos i = sqrt((n² − 1)/3) = 0.5089 for n = 1.333, so i = 59.41°,
  // r = asin(sin i / n) = 40.22° and the deviation 180° + 2i − 4r = 137.94°. No ray bends
  // less; the light piles up just beyond it (a caustic, density ∝ 1/√(θ − 137.94°)), so
  // 0.06° of it falls in [137°, 138°) and the peak bin is [138°, 139°).
  int peak = 90;
  for (int k = 90; k < 180; ++k) {
    if (phase_at_degree(k) > phase_at_degree(peak)) peak = k;
  }
  EXPECT_EQ(peak, 138);
  // Alexander's dark band between the secondary (~129°) and primary bows: no ray of one or two
  // internal reflections ends there, so it is darker than either side.
  EXPECT_LT(phase_at_degree(133), 0.2 * phase_at_degree(138));
  EXPECT_LT(phase_at_degree(133), phase_at_degree(127));
}

TEST(DropOptics, LargeWaterDropsScatterForwardWithTheTextbookAsymmetry) {
  // Large water spheres: g ≈ 0.88 including diffraction (Hansen & Travis 1974, Fig. 12, the
  // size-parameter limit; van de Hulst 1957 §12.6). Diffraction carries half the extinction
  // with g = 1, so geometric optics alone has g = 2·0.88 − 1 ≈ 0.76.
  EXPECT_NEAR(water().asymmetry, 0.77, 0.02);
  EXPECT_NEAR(0.5 * (1.0 + water().asymmetry), 0.88, 0.01);
  // Nearly all of it within 90° of forward, and a glare around the light: P(0°) is hundreds of
  // times P(90°).
  EXPECT_GT(water().forward_share, 0.9);
  EXPECT_GT(phase_at_degree(0), 100.0 * phase_at_degree(90));
}

TEST(DropOptics, PovrayLobesCarryTheForwardAndBackwardLightWithTheRightShape) {
  const PovrayLobes lobes = fit_povray_lobes(water());
  // Mean forward cosine 0.861 → b = (2·0.861 − 1)/(1 − 0.861) ≈ 5.2.
  EXPECT_NEAR(lobes.brilliance, 5.2, 0.2);
  // Energy: A/(2(b + 1)) = forward share 0.94 → A ≈ 11.7, diffuse A/4 ≈ 2.9.
  EXPECT_NEAR(lobes.back * 4.0 / (2.0 * (lobes.brilliance + 1.0)), water().forward_share, 1e-12);
  EXPECT_NEAR(lobes.front * 4.0 / (2.0 * (lobes.brilliance + 1.0)), 1.0 - water().forward_share,
              1e-12);
  // The lobe follows the table where most forward light goes: within 35 % at 20°–50°.
  for (const int degree : {20, 30, 40, 50}) {
    const double lobe =
        4.0 * lobes.back *
        std::pow(std::cos((degree + 0.5) * std::numbers::pi / 180.0), lobes.brilliance);
    EXPECT_NEAR(lobe / phase_at_degree(degree), 1.0, 0.35) << degree << "°";
  }
}

TEST(DropOptics, TheCachedTwentyThousandRayTraceAgreesWithTheFineOne) {
  EXPECT_NEAR(water_drop_scattering().asymmetry, water().asymmetry, 1e-3);
  EXPECT_NEAR(water_drop_scattering().forward_mean_cosine, water().forward_mean_cosine, 1e-3);
  EXPECT_NEAR(water_drop_scattering().forward_share, water().forward_share, 1e-3);
}

}  // namespace
}  // namespace raintrace::sim
