// Marshall-Palmer moments and the rate-matched size model.
#include "sim/drop_size.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/terminal_velocity.h"

namespace raintrace::sim {
namespace {

// Simpson's rule, to check the closed forms independently.
template <typename F>
double integrate(F f, double a, double b, int n = 20000) {
  const double h = (b - a) / n;
  double s = f(a) + f(b);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * f(a + i * h);
  return s * h / 3.0;
}

TEST(MarshallPalmer, LambdaFollowsRate) {
  EXPECT_NEAR(marshall_palmer_lambda_per_mm(1.0), 4.1, 1e-12);
  // 4.1·5^−0.21 = 4.1·0.713 = 2.924
  EXPECT_NEAR(marshall_palmer_lambda_per_mm(5.0), 4.1 * std::pow(5.0, -0.21), 1e-12);
}

TEST(MarshallPalmer, NumberDensityIsTheIntegralOverTheTruncation) {
  const double l = marshall_palmer_lambda_per_mm(5.0);
  const double numeric = integrate([&](double d) { return 8000.0 * std::exp(-l * d); }, 0.5, 6.0);
  EXPECT_NEAR(marshall_palmer_number_density(5.0, 0.5, 6.0), numeric, 1e-6 * numeric);
  // Untruncated: N0/Λ.
  EXPECT_NEAR(marshall_palmer_number_density(5.0, 0.0, 1e3), 8000.0 / l, 1e-9);
}

TEST(MarshallPalmer, MeanDiameterIsOneOverLambdaAdjustedForTruncation) {
  const double l = marshall_palmer_lambda_per_mm(5.0);
  EXPECT_NEAR(marshall_palmer_mean_diameter_mm(5.0, 0.0, 1e3), 1.0 / l, 1e-12);
  // Truncated below at Dmin shifts the mean by Dmin (memorylessness of the exponential),
  // less a little for the upper cut.
  const double n = integrate([&](double d) { return std::exp(-l * d); }, 0.5, 6.0);
  const double m = integrate([&](double d) { return d * std::exp(-l * d); }, 0.5, 6.0);
  EXPECT_NEAR(marshall_palmer_mean_diameter_mm(5.0, 0.5, 6.0), m / n, 1e-9);
  EXPECT_NEAR(marshall_palmer_mean_diameter_mm(5.0, 0.5, 1e3), 0.5 + 1.0 / l, 1e-12);
}

TEST(MarshallPalmer, ExtinctionIsTwiceTheCrossSectionOfTheDrops) {
  // Untruncated: Q·π/4·N0·2/Λ³ = π·N0/Λ³ = 0.365·R^0.63 /km, the Marshall-Palmer rain
  // extinction used for optical links; at 5 mm/h 1.0e-3 /m (issue 12's figure).
  EXPECT_NEAR(marshall_palmer_extinction_per_m(5.0, 0.0, 50.0), 1.006e-3, 0.005e-3);
  for (const double r : {1.0, 25.0}) {
    EXPECT_NEAR(marshall_palmer_extinction_per_m(r, 0.0, 50.0), 0.365e-3 * std::pow(r, 0.63),
                0.005 * 0.365e-3 * std::pow(r, 0.63));
  }
  const double l = marshall_palmer_lambda_per_mm(5.0);
  const double numeric = integrate(
      [&](double d) {
        return 2.0 * std::numbers::pi / 4.0 * d * d * 1e-6 * 8000.0 * std::exp(-l * d);
      },
      0.5, 6.0);
  EXPECT_NEAR(marshall_palmer_extinction_per_m(5.0, 0.5, 6.0), numeric, 1e-6 * numeric);
}

TEST(DropSizeModel, CrossSectionIsHalfTheExtinctionOfTheRateMatchedDistribution) {
  // The model rescales N0 so the drops carry the rate; its cross-section ∫N·πD²/4 is then
  // that scale times half the Marshall-Palmer extinction (Q = 2 counts diffraction too).
  RainParams rain;
  rain.rate_mm_per_h = 5.0;
  const DropSizeModel model(rain);
  EXPECT_NEAR(model.cross_section_per_m(),
              model.concentration_scale() * 0.5 * marshall_palmer_extinction_per_m(5.0, 0.5, 6.0),
              1e-4 * model.cross_section_per_m());
  // One size: N·πD²/4.
  rain.distribution = DropSizeDistribution::uniform;
  rain.diameter_min_mm = 2.0;
  rain.diameter_max_mm = 2.0;
  const DropSizeModel single(rain);
  EXPECT_NEAR(single.cross_section_per_m(),
              single.number_density_per_m3() * std::numbers::pi / 4.0 * 4e-6,
              1e-9 * single.cross_section_per_m());
}

TEST(MarshallPalmer, WaterContentMatchesPublishedFit) {
  // Untruncated LWC = π·ρ·N0/Λ⁴ = 0.0889 g/m³ at 1 mm/h, the textbook 0.089·R^0.84.
  for (const double r : {1.0, 5.0, 25.0}) {
    EXPECT_NEAR(marshall_palmer_water_content(r, 0.0, 50.0), 0.0889 * std::pow(r, 0.84),
                0.01 * 0.0889 * std::pow(r, 0.84));
  }
  const double l = marshall_palmer_lambda_per_mm(5.0);
  const double numeric = integrate(
      [&](double d) {
        return 1e6 * std::numbers::pi / 6.0 * d * d * d * 1e-9 * 8000.0 * std::exp(-l * d);
      },
      0.5, 6.0);
  EXPECT_NEAR(marshall_palmer_water_content(5.0, 0.5, 6.0), numeric, 1e-6 * numeric);
}

TEST(DropSizeModel, KeepsTheMarshallPalmerShape) {
  RainParams rain;  // 5 mm/h, [0.5, 6] mm
  const DropSizeModel model(rain);
  // Density is the Marshall-Palmer integral times the applied N0 scale.
  EXPECT_NEAR(model.number_density_per_m3() / model.concentration_scale(),
              marshall_palmer_number_density(5.0, 0.5, 6.0),
              1e-4 * marshall_palmer_number_density(5.0, 0.5, 6.0));
  EXPECT_NEAR(model.mean_diameter_m() * 1e3, marshall_palmer_mean_diameter_mm(5.0, 0.5, 6.0), 1e-5);
  // Marshall-Palmer is self-consistent to ~20 %: the rescale stays near 1.
  EXPECT_GT(model.concentration_scale(), 0.7);
  EXPECT_LT(model.concentration_scale(), 1.3);
}

TEST(DropSizeModel, SamplesFollowTheDistribution) {
  RainParams rain;
  const DropSizeModel model(rain);
  const int n = 100000;
  double sum = 0.0;
  for (int k = 0; k < n; ++k) sum += model.sample_in_air((k + 0.5) / n);
  EXPECT_NEAR(sum / n * 1e3, marshall_palmer_mean_diameter_mm(5.0, 0.5, 6.0), 1e-3);
  EXPECT_NEAR(model.sample_in_air(0.0), 0.5e-3, 1e-9);
  // Inverse of the truncated exponential CDF: D = Dmin − ln(1 − u·(1 − e^(−Λ(Dmax−Dmin))))/Λ.
  const double l = marshall_palmer_lambda_per_mm(5.0);
  for (const double u : {0.3, 0.9, 0.999}) {
    const double d_mm = 0.5 - std::log(1.0 - u * (1.0 - std::exp(-l * 5.5))) / l;
    EXPECT_NEAR(model.sample_in_air(u) * 1e3, d_mm, 1e-3) << u;
  }
}

TEST(DropSizeModel, FluxCarriesExactlyTheConfiguredRainRate) {
  for (const auto dist : {DropSizeDistribution::marshall_palmer, DropSizeDistribution::uniform}) {
    RainParams rain;
    rain.distribution = dist;
    rain.rate_mm_per_h = 12.0;
    rain.diameter_min_mm = 0.6;
    rain.diameter_max_mm = dist == DropSizeDistribution::uniform ? 1.4 : 6.0;
    const DropSizeModel model(rain);
    // Water flux = number flux × mean volume of a crossing drop (drawn from the flux law).
    const int n = 100000;
    double volume = 0.0;
    for (int k = 0; k < n; ++k) {
      const double d = model.sample_in_flux((k + 0.5) / n);
      volume += std::numbers::pi / 6.0 * d * d * d;
    }
    const double mm_per_h = model.number_flux_per_m2_s() * volume / n * 1e3 * 3600.0;
    EXPECT_NEAR(mm_per_h, 12.0, 0.01 * 12.0);
  }
}

TEST(DropSizeModel, UniformIsFlat) {
  RainParams rain;
  rain.distribution = DropSizeDistribution::uniform;
  rain.diameter_min_mm = 0.6;
  rain.diameter_max_mm = 1.4;
  const DropSizeModel model(rain);
  EXPECT_NEAR(model.sample_in_air(0.25), 0.8e-3, 1e-7);
  EXPECT_NEAR(model.mean_diameter_m(), 1.0e-3, 1e-8);
}

TEST(DropSizeModel, NoRainNoDrops) {
  RainParams rain;
  rain.rate_mm_per_h = 0.0;
  const DropSizeModel model(rain);
  EXPECT_EQ(model.number_density_per_m3(), 0.0);
  EXPECT_EQ(model.number_flux_per_m2_s(), 0.0);
}

}  // namespace
}  // namespace raintrace::sim
