// Gust function values by hand, turbulence statistics and divergence.
#include "sim/wind.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace raintrace::sim {
namespace {

TEST(Wind, GustFunctionMatchesHandValues) {
  // t = 0.02: cos(0.02π)·cos(0.06π)·cos(0.1π)·cos(0.14π) = 0.998027·0.982287·0.951057·0.904827
  // = 0.843631; sin(25π·0.02) = sin(π/2) = 1 → w = −0.0843631.
  EXPECT_NEAR(gust_function(0.02), -0.0843631, 1e-6);
  // t = 0.06: 0.982287·0.844328·0.587785·0.248690 = 0.121235; sin(1.5π) = −1 → +0.0121235.
  EXPECT_NEAR(gust_function(0.06), 0.0121235, 1e-6);
  // t = 0 and t = 1: sin(25πt) = 0.
  EXPECT_NEAR(gust_function(0.0), 0.0, 1e-15);
  EXPECT_NEAR(gust_function(1.0), 0.0, 1e-12);
  // t = 0.1: cos(5π·0.1) = cos(π/2) = 0.
  EXPECT_NEAR(gust_function(0.1), 0.0, 1e-12);
}

TEST(Wind, GustsScaleAlongTheirHorizontalDirection) {
  WindParams p;
  p.velocity_m_per_s = {1.0, 0.0, 2.0};
  p.gusts = true;
  p.gust_strength = 20.0;
  p.gust_direction = {0.0, 5.0, 3.0};  // y ignored → +z
  p.gust_period_s = 2.0;               // eq. 5 as printed
  const Wind wind(p, 1);
  const glm::dvec3 w = wind.uniform_at(0.02);
  EXPECT_NEAR(w.x, 1.0, 1e-12);
  EXPECT_NEAR(w.y, 0.0, 1e-12);
  EXPECT_NEAR(w.z, 2.0 + 20.0 * -0.0843631, 1e-5);
}

TEST(Wind, GustPeriodStretchesEquationFiveWithoutChangingIt) {
  WindParams p;
  p.gusts = true;
  p.gust_strength = 20.0;
  // 2 s is eq. 5 as printed: the gust at t is 20·w(t).
  p.gust_period_s = 2.0;
  const Wind printed(p, 1);
  for (const double t : {0.02, 0.06, 0.37, 1.5}) {
    EXPECT_NEAR(printed.uniform_at(t).x, 20.0 * gust_function(t), 1e-12) << t;
  }
  // 20 s: the same curve, ten times slower — at 10·t it blows as the printed one did at t.
  p.gust_period_s = 20.0;
  const Wind slow(p, 1);
  for (const double t : {0.02, 0.06, 0.37, 1.5}) {
    EXPECT_NEAR(slow.uniform_at(10.0 * t).x, printed.uniform_at(t).x, 1e-9) << t;
  }
  // The whole pattern repeats after one period, as eq. 5 does after 2 s.
  EXPECT_NEAR(slow.uniform_at(3.7 + 20.0).x, slow.uniform_at(3.7).x, 1e-9);
  EXPECT_NEAR(gust_function(0.37 + kGustFunctionPeriodS), gust_function(0.37), 1e-12);
}

TEST(Wind, TurbulenceHasTheRequestedRmsAndNoDivergence) {
  WindParams p;
  p.turbulence_m_per_s = 2.0;
  p.turbulence_scale_m = 3.0;
  const Wind wind(p, 7);
  // RMS over a large cube of sample points: the modes are incoherent, so the mean square is
  // Σ a²/2 = turbulence² (to sampling error of a few %).
  double sum = 0.0;
  int n = 0;
  double max_div = 0.0;
  const float h = 1e-2f;
  for (int i = 0; i < 30; ++i) {
    for (int j = 0; j < 30; ++j) {
      for (int k = 0; k < 30; ++k) {
        const glm::vec3 x{static_cast<float>(i) * 1.37f, static_cast<float>(j) * 1.11f,
                          static_cast<float>(k) * 1.53f};
        const glm::vec3 w = wind.turbulence_at(x, 0.0);
        sum += static_cast<double>(w.x * w.x + w.y * w.y + w.z * w.z);
        ++n;
        const float div = (wind.turbulence_at(x + glm::vec3{h, 0, 0}, 0.0).x -
                           wind.turbulence_at(x - glm::vec3{h, 0, 0}, 0.0).x +
                           wind.turbulence_at(x + glm::vec3{0, h, 0}, 0.0).y -
                           wind.turbulence_at(x - glm::vec3{0, h, 0}, 0.0).y +
                           wind.turbulence_at(x + glm::vec3{0, 0, h}, 0.0).z -
                           wind.turbulence_at(x - glm::vec3{0, 0, h}, 0.0).z) /
                          (2 * h);
        max_div = std::max(max_div, static_cast<double>(std::abs(div)));
      }
    }
  }
  EXPECT_NEAR(std::sqrt(sum / n), 2.0, 0.3);
  // Gradients are ~ amplitude·k ≈ 2·2.1 = 4 /s; divergence is zero up to float differencing.
  EXPECT_LT(max_div, 0.05);
}

TEST(Wind, SinApproxMatchesStdSin) {
  // The turbulence phase stays well inside ±100 rad for any scene (k·q with |q| < 1 km needs
  // k < 0.1 rad/m); over that range float rounding of x − nπ gives ~1e-7.
  double worst = 0.0;
  for (float x = -100.0f; x < 100.0f; x += 0.00731f) {
    worst = std::max(worst, std::abs(static_cast<double>(sin_approx(x)) - std::sin(double{x})));
  }
  EXPECT_LT(worst, 2e-7);
}

TEST(Wind, TurbulenceLipschitzBoundsDifferences) {
  WindParams p;
  p.turbulence_m_per_s = 1.5;
  p.turbulence_scale_m = 2.0;
  const Wind wind(p, 3);
  // Four modes of amplitude 1.5·sqrt(2/4) and wave number 2π/2: L = 4·1.0607·3.1416 = 13.33.
  EXPECT_NEAR(wind.turbulence_lipschitz_per_s(), 13.33, 0.01);
  for (int i = 0; i < 200; ++i) {
    const glm::vec3 a{0.1f * static_cast<float>(i), 1.0f, 0.3f};
    const glm::vec3 b = a + glm::vec3{0.01f, -0.02f, 0.005f};
    EXPECT_LE(glm::length(wind.turbulence_at(a, 0.5) - wind.turbulence_at(b, 0.5)),
              wind.turbulence_lipschitz_per_s() * glm::length(a - b) + 1e-5);
  }
}

TEST(Wind, NoTurbulenceByDefault) {
  const Wind wind(WindParams{}, 1);
  EXPECT_FALSE(wind.has_turbulence());
  EXPECT_EQ(wind.at({1, 2, 3}, 0.5), glm::vec3(0.0f));
}

}  // namespace
}  // namespace raintrace::sim
