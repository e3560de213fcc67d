// Sensor noise is as strong as its contract says at each light level (shot noise over a read
// floor, scaled with the frame's width), zero-mean, independent between colour channels,
// clumped over about a pixel, repeatable per (seed, frame), and leaves the image alone at 0.
#include "film/sensor_noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "film/image_sums_test_support.h"

namespace raintrace::film {
namespace {

/// Mean and RMS of (out − L) over channel c of a flat image of scene-linear value L.
testing::Departure noise_stats(float linear, double strength, int c) {
  RgbImage image(testing::kStatsSide, testing::kStatsSide, linear);
  apply_sensor_noise(image, strength, 7, 3);
  return testing::departure_from(image, linear, c);
}

TEST(SensorNoise, RmsIsShotNoiseOverAReadFloor) {
  // Strength s at 1920 px: one electron is worth 0.18·s²; mid-grey holds 1/s² electrons, so its
  // relative RMS is s (times √(1 + 9·s²) for the read noise: 1.011 at s = 0.05).
  const double s = 0.05, electron = 0.18 * s * s;
  EXPECT_NEAR(sensor_noise_rms(s, 1920, 0.18) / 0.18, s * std::sqrt(1 + 9 * s * s), 1e-12);
  // Shot noise alone grows as √L: four times the light, twice the noise (less the read floor).
  const double shot = [&](double l) { return std::sqrt(electron * l); }(0.72);
  EXPECT_NEAR(sensor_noise_rms(s, 1920, 0.72), std::hypot(shot, 3 * electron), 1e-15);
  // In the dark only the read noise is left: 3 electrons; negative light counts as none.
  EXPECT_DOUBLE_EQ(sensor_noise_rms(s, 1920, 0.0), 3 * electron);
  EXPECT_DOUBLE_EQ(sensor_noise_rms(s, 1920, -1.0), 3 * electron);
  // Half the width: each pixel gathers four photosites' light, half the relative noise.
  EXPECT_NEAR(sensor_noise_rms(s, 960, 0.18), sensor_noise_rms(s / 2, 1920, 0.18), 1e-15);
  EXPECT_EQ(sensor_noise_rms(0.0, 1920, 0.5), 0.0);
}

TEST(SensorNoise, IsZeroMeanWithTheContractedRmsInEveryChannel) {
  // Values well above σ so the clamp at 0 never acts (|n| < 6.93). Standard errors as in
  // grain_test.cpp: the mean within 8/512 of the RMS (clumping doubles the independent 4/512),
  // the RMS within 1 %.
  for (float linear : {0.18f, 0.02f, 2.0f}) {
    const double expected = sensor_noise_rms(0.2, testing::kStatsSide, linear);
    for (int c = 0; c < 3; ++c) {
      const testing::Departure s = noise_stats(linear, 0.2, c);
      EXPECT_NEAR(s.mean, 0.0, 8.0 * expected / testing::kStatsSide)
          << "L " << linear << " channel " << c;
      EXPECT_NEAR(s.rms, expected, 0.01 * expected) << "L " << linear << " channel " << c;
    }
  }
}

// R, G and B draw their own noise: the correlation between channels is that of independent
// draws (standard error ≈ 2/√N with the clumping, 0.004; allow 0.02). Neighbours within a
// channel share it as pixel_noise.h says (8/18 across a side).
TEST(SensorNoise, ChannelsAreIndependentAndNeighboursClump) {
  RgbImage image(testing::kStatsSide, testing::kStatsSide, 0.5f);
  apply_sensor_noise(image, 0.3, 1, 1);
  const auto correlation = [&](int c1, int c2, int dx) {
    double sum = 0.0, var1 = 0.0, var2 = 0.0;
    for (int y = 0; y < testing::kStatsSide; ++y) {
      for (int x = 0; x + dx < testing::kStatsSide; ++x) {
        const double a = image.at(x, y, c1) - 0.5, b = image.at(x + dx, y, c2) - 0.5;
        sum += a * b;
        var1 += a * a;
        var2 += b * b;
      }
    }
    return sum / std::sqrt(var1 * var2);
  };
  EXPECT_NEAR(correlation(0, 1, 0), 0.0, 0.02);
  EXPECT_NEAR(correlation(1, 2, 0), 0.0, 0.02);
  EXPECT_NEAR(correlation(0, 2, 0), 0.0, 0.02);
  EXPECT_NEAR(correlation(1, 1, 1), 8.0 / 18.0, 0.02);
}

TEST(SensorNoise, SameSeedAndFrameGiveIdenticalNoiseOthersDiffer) {
  RgbImage a(64, 48, 0.1f), b(64, 48, 0.1f), next_frame(64, 48, 0.1f);
  apply_sensor_noise(a, 0.2, 11, 5);
  apply_sensor_noise(b, 0.2, 11, 5);
  apply_sensor_noise(next_frame, 0.2, 11, 6);
  EXPECT_EQ(a.pixels, b.pixels);
  int same = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) same += a.pixels[i] == next_frame.pixels[i];
  EXPECT_LT(same, 10);
}

TEST(SensorNoise, BlackStaysNonNegativeAndZeroStrengthIsANoOp) {
  RgbImage black(64, 64, 0.0f);
  apply_sensor_noise(black, 0.5, 3, 1);
  double sum = 0.0;
  for (float v : black.pixels) {
    EXPECT_GE(v, 0.0f);
    sum += v;
  }
  // Half the read noise's draws are clamped away: the mean is lifted by about σ(0)/√(2π).
  const double lift = sensor_noise_rms(0.5, 64, 0.0) / std::sqrt(2 * std::numbers::pi);
  EXPECT_NEAR(sum / double(black.pixels.size()), lift, 0.2 * lift);

  RgbImage image(8, 8, 0.5f);
  apply_sensor_noise(image, 0.0, 1, 1);
  for (float v : image.pixels) EXPECT_EQ(v, 0.5f);
  EXPECT_THROW(apply_sensor_noise(image, 0.6, 1, 1), std::invalid_argument);
  EXPECT_THROW(apply_sensor_noise(image, -0.01, 1, 1), std::invalid_argument);
}

}  // namespace
}  // namespace raintrace::film
