// The rain medium: extinction from the drop size distribution, δ-scaling.
#include "sim/rain_medium.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/drop_optics.h"
#include "sim/drop_size.h"

namespace raintrace::sim {
namespace {

TEST(RainMedium, ExtinctionFollowsTheDropSizeDistributionAtTheConfiguredRate) {
  // 5 mm/h between 0.5 and 6 mm: Marshall-Palmer's closed form, times the concentration scale
  // the simulation applies so that its drops carry exactly 5 mm/h. Untruncated Marshall-Palmer
  // would give 1.0e-3 /m; cutting the drops below 0.5 mm removes 0.5 % of it, and the
  // rescaling for measured fall speeds moves it by the scale.
  RainParams rain;
  const DropSizeModel sizes(rain);
  const RainMediumOptics optics = rain_medium_optics(rain);
  EXPECT_NEAR(optics.extinction_per_m,
              sizes.concentration_scale() * marshall_palmer_extinction_per_m(5.0, 0.5, 6.0),
              1e-4 * optics.extinction_per_m);
  EXPECT_GT(optics.extinction_per_m, 0.7e-3);
  EXPECT_LT(optics.extinction_per_m, 1.3e-3);
  // The picture sees half of it: the diffracted half stays inside the pixel.
  EXPECT_DOUBLE_EQ(optics.image_extinction_per_m, 0.5 * optics.extinction_per_m);
  // Heavier rain: untruncated Marshall-Palmer grows as R^0.63 (×4.27 from 5 to 50 mm/h); the
  // 6 mm cut removes more of heavy rain's large drops, which the rate-matching puts back
  // as more drops of the rest, so the simulated rain's medium grows a little faster.
  rain.rate_mm_per_h = 50.0;
  const DropSizeModel heavy(rain);
  const double heavy_extinction = rain_medium_optics(rain).extinction_per_m;
  EXPECT_NEAR(heavy_extinction,
              heavy.concentration_scale() * marshall_palmer_extinction_per_m(50.0, 0.5, 6.0),
              1e-4 * heavy_extinction);
  EXPECT_GT(heavy_extinction / optics.extinction_per_m, std::pow(10.0, 0.63));
  rain.rate_mm_per_h = 0.0;
  EXPECT_EQ(rain_medium_optics(rain).extinction_per_m, 0.0);
}

TEST(RainMedium, DeltaScalingKeepsTheGeometricOpticsAsymmetry) {
  // With diffraction (half the extinction, g = 1) the asymmetry is (1 + g_geo)/2; removing the
  // forward peak f = ½ gives (g − f)/(1 − f) = g_geo again (Joseph et al. 1976).
  const double g_geo = water_drop_scattering().asymmetry;
  const double g_total = 0.5 * (1.0 + g_geo);
  EXPECT_NEAR(rain_medium_optics(RainParams{}).eccentricity, (g_total - 0.5) / (1.0 - 0.5), 1e-12);
  EXPECT_NEAR(rain_medium_optics(RainParams{}).eccentricity, 0.77, 0.02);
}

}  // namespace
}  // namespace raintrace::sim
