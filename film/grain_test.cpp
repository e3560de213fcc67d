// Grain is deterministic per (seed, frame), zero-mean, as strong as its contract says at each
// grey level, shared between neighbours as its contract says, and grey (shared by R, G and B).
#include "film/grain.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "film/image_sums_test_support.h"

namespace raintrace::film {
namespace {

/// Mean and RMS of (out − v) over channel 0 of a flat image of grey v.
testing::Departure grain_stats(float v, double strength, std::uint64_t seed, std::int64_t frame) {
  RgbImage image(testing::kStatsSide, testing::kStatsSide, v);
  apply_grain(image, strength, seed, frame);
  return testing::departure_from(image, v, 0);
}

TEST(Grain, RmsFollowsTheBooleanModelAndSelwynsLaw) {
  // 2·√(v(1 − v)): 1 at mid-grey, 0.6 at 0.1 and 0.9, 0 at black and white.
  EXPECT_DOUBLE_EQ(grain_rms(0.04, 1920, 0.5), 0.04);
  EXPECT_NEAR(grain_rms(0.04, 1920, 0.1), 0.04 * 0.6, 1e-12);
  EXPECT_NEAR(grain_rms(0.04, 1920, 0.9), 0.04 * 0.6, 1e-12);
  EXPECT_EQ(grain_rms(0.04, 1920, 0.0), 0.0);
  EXPECT_EQ(grain_rms(0.04, 1920, 1.0), 0.0);
  EXPECT_EQ(grain_rms(0.04, 1920, 1.5), 0.0);
  // Half the width: pixels four times the area average four times the grains, half the RMS.
  EXPECT_DOUBLE_EQ(grain_rms(0.04, 960, 0.5), 0.02);
}

TEST(Grain, IsZeroMeanWithTheContractedRms) {
  // Mid-grey at 1920 px wide (512 px here: the RMS scales by 512/1920), strength 0.1: no value
  // reaches the clamp (|n| < 6.93, 6.93 · 0.1 · 512/1920 < 0.5). The sample mean of N unit-variance
  // values has standard error 1/√N = 1/512 for independent ones; neighbours sharing grain widen
  // it (the kernel's sum over its root sum of squares, 36/18 = 2): allow 4 of the wider ones,
  // times the RMS. The sample RMS has relative standard error ≈ √((κ − 1) / 4N) for independent
  // values, κ ≤ 3: 0.14 %, a few times that with the correlation; allow 1 %.
  for (float v : {0.5f, 0.2f, 0.85f}) {
    const double expected_rms = grain_rms(0.1, testing::kStatsSide, v);
    const testing::Departure s = grain_stats(v, 0.1, 7, 3);
    EXPECT_NEAR(s.mean, 0.0, 8.0 * expected_rms / testing::kStatsSide) << "grey " << v;
    EXPECT_NEAR(s.rms, expected_rms, 0.01 * expected_rms) << "grey " << v;
  }
}

TEST(Grain, SameSeedAndFrameGiveIdenticalGrainOthersDiffer) {
  RgbImage a(64, 48, 0.4f), b(64, 48, 0.4f), next_frame(64, 48, 0.4f), other_seed(64, 48, 0.4f);
  apply_grain(a, 0.2, 11, 5);
  apply_grain(b, 0.2, 11, 5);
  apply_grain(next_frame, 0.2, 11, 6);
  apply_grain(other_seed, 0.2, 12, 5);
  EXPECT_EQ(a.pixels, b.pixels);
  int same_frame = 0, same_seed = 0;
  for (std::size_t i = 0; i < a.pixel_count(); ++i) {
    same_frame += a.pixels[i * 3] == next_frame.pixels[i * 3];
    same_seed += a.pixels[i * 3] == other_seed.pixels[i * 3];
  }
  // Two independent draws agree in a pixel only when both round to the same float: rare.
  EXPECT_LT(same_frame, 10);
  EXPECT_LT(same_seed, 10);
}

// Neighbours share grain as the (1, 4, 1) ⊗ (1, 4, 1) kernel says: correlation (1·4 + 4·1) ·
// 18 / 18² = 8/18 across a side, 1/18 two pixels apart, none three apart (the kernels no longer
// overlap). A correlation coefficient over N samples has standard error ≈ 1/√N ≈ 0.002 when
// independent; allow 0.02 (the sums here run over correlated pairs).
TEST(Grain, NeighboursShareGrainOverAboutAPixel) {
  RgbImage image(testing::kStatsSide, testing::kStatsSide, 0.5f);
  apply_grain(image, 0.2, 1, 1);
  const auto correlation = [&](int dx, int dy) {
    double sum = 0.0, var = 0.0;
    for (int y = 0; y + dy < testing::kStatsSide; ++y) {
      for (int x = 0; x + dx < testing::kStatsSide; ++x) {
        const double d = image.at(x, y, 0) - 0.5;
        sum += d * (image.at(x + dx, y + dy, 0) - 0.5);
        var += d * d;
      }
    }
    return sum / var;
  };
  EXPECT_NEAR(correlation(1, 0), 8.0 / 18.0, 0.02);
  EXPECT_NEAR(correlation(0, 1), 8.0 / 18.0, 0.02);
  EXPECT_NEAR(correlation(2, 0), 1.0 / 18.0, 0.02);
  EXPECT_NEAR(correlation(0, 3), 0.0, 0.02);
}

TEST(Grain, IsGreyAndLeavesBlackAndWhiteAlone) {
  RgbImage image(32, 32);
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) {
      const float v = x < 8 ? 0.0f : (x < 16 ? 1.0f : 0.3f);
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = v;
    }
  }
  const RgbImage before = image;
  apply_grain(image, 0.3, 2, 9);
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) {
      if (x < 16) {
        EXPECT_EQ(image.at(x, y, 0), before.at(x, y, 0));
      }
      EXPECT_EQ(image.at(x, y, 0), image.at(x, y, 1));
      EXPECT_EQ(image.at(x, y, 0), image.at(x, y, 2));
    }
  }
}

TEST(Grain, ZeroStrengthIsANoOpAndRangeIsChecked) {
  RgbImage image(8, 8, 0.5f);
  apply_grain(image, 0.0, 1, 1);
  for (float v : image.pixels) EXPECT_EQ(v, 0.5f);
  EXPECT_THROW(apply_grain(image, 0.6, 1, 1), std::invalid_argument);
  EXPECT_THROW(apply_grain(image, -0.01, 1, 1), std::invalid_argument);
}

}  // namespace
}  // namespace raintrace::film
