// Sensor noise is as strong as its contract says at each light level (shot noise over a read
// floor, scaled with the frame's width), zero-mean, fine in luminance and clumped over about a
// pixel, its colour smoothed into faint blotches, repeatable per (seed, frame), and leaves the
// image alone at 0.
#include "film/sensor_noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "film/image_sums_test_support.h"

namespace raintrace::film {
namespace {

/// A flat image of scene-linear value L, `width` × kStatsSide, with the noise applied.
RgbImage noisy_flat(float linear, double strength, int width = testing::kStatsSide) {
  RgbImage image(width, testing::kStatsSide, linear);
  apply_sensor_noise(image, strength, 7, 3);
  return image;
}

/// The noise of pixel (x, y) split as the contract splits it: its luminance part (the mean of
/// the three channels' departures from L) and channel c's colour part (its departure from that
/// mean).
double luminance_part(const RgbImage& image, float linear, int x, int y) {
  return (image.at(x, y, 0) + image.at(x, y, 1) + image.at(x, y, 2)) / 3.0 - linear;
}
double colour_part(const RgbImage& image, float linear, int x, int y, int c) {
  return image.at(x, y, c) - linear - luminance_part(image, linear, x, y);
}

/// Correlation of `part` with itself dx pixels to the right, over the whole image.
template <typename Part>
double correlation_across(const RgbImage& image, int dx, Part part) {
  double sum = 0.0, var1 = 0.0, var2 = 0.0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x + dx < image.width; ++x) {
      const double a = part(x, y), b = part(x + dx, y);
      sum += a * b;
      var1 += a * a;
      var2 += b * b;
    }
  }
  return sum / std::sqrt(var1 * var2);
}

/// RMS of `part` over the whole image.
template <typename Part>
double rms_of(const RgbImage& image, Part part) {
  double sum = 0.0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) sum += part(x, y) * part(x, y);
  }
  return std::sqrt(sum / double(image.pixel_count()));
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

// The luminance part is the mean of three channels' independent photosite noise, which the
// camera keeps: RMS σ(L)/√3 at every light level. Values well above σ so the clamp at 0 never
// acts (|n| < 6.93). Standard errors as in grain_test.cpp: the mean within 8/512 of the RMS
// (clumping doubles the independent 4/512), the RMS within 1 %.
TEST(SensorNoise, LuminanceNoiseIsZeroMeanWithTheContractedRms) {
  for (float linear : {0.18f, 0.02f, 2.0f}) {
    const double expected = sensor_noise_rms(0.2, testing::kStatsSide, linear) / std::sqrt(3.0);
    const RgbImage image = noisy_flat(linear, 0.2);
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) sum += luminance_part(image, linear, x, y);
    }
    EXPECT_NEAR(sum / double(image.pixel_count()), 0.0, 8.0 * expected / testing::kStatsSide)
        << "L " << linear;
    const double rms =
        rms_of(image, [&](int x, int y) { return luminance_part(image, linear, x, y); });
    EXPECT_NEAR(rms, expected, 0.01 * expected) << "L " << linear;
  }
}

// The colour part, smoothed by a Gaussian of 4 px at 1920 px wide: faint beside the luminance
// part and spread into blotches several pixels across, where the luminance part clumps over a
// pixel only (pixel_noise.h: 8/18 across a side, 0 three apart). Unsmoothed the colour part
// would be √2 times the luminance part and as fine. Measured on a 1920-wide frame: 0.197–0.199
// of the luminance part, correlated 0.78 four pixels apart. Bounds: under a third of the raw
// speckle's √2 (0.45), and something left of it (0.1: the blotches of a real camera).
TEST(SensorNoise, ColourNoiseIsSmoothedIntoFaintBlotches) {
  const float linear = 0.5f;
  const RgbImage image = noisy_flat(linear, 0.2, 1920);
  const auto luminance = [&](int x, int y) { return luminance_part(image, linear, x, y); };
  const double luminance_rms = rms_of(image, luminance);
  for (int c = 0; c < 3; ++c) {
    const auto colour = [&](int x, int y) { return colour_part(image, linear, x, y, c); };
    const double ratio = rms_of(image, colour) / luminance_rms;
    EXPECT_LT(ratio, 0.45) << "channel " << c << ": the colour speckle is not smoothed";
    EXPECT_GT(ratio, 0.1) << "channel " << c << ": no colour noise is left";
    EXPECT_GT(correlation_across(image, 4, colour), 0.6) << "channel " << c << ": not blotches";
  }
  EXPECT_NEAR(correlation_across(image, 1, luminance), 8.0 / 18.0, 0.02);
  EXPECT_NEAR(correlation_across(image, 3, luminance), 0.0, 0.02);
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
