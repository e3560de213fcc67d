// Metrics on small in-memory images whose differences are set by hand, so every expected
// number can be derived on paper (derivations in the comments).
#include "compare/metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace raintrace::compare {
namespace {

Image gradient(int w, int h, int c) {
  Image img(w, h, c);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int k = 0; k < c; ++k) img.at(x, y, k) = float((x * 7 + y * 13 + k * 5) % 17) / 16.0f;
  return img;
}

TEST(Metrics, IdenticalImagesHaveZeroErrorInfinitePsnrAndPass) {
  const Image a = gradient(20, 15, 3);
  const Metrics m = compute_metrics(a, a);
  EXPECT_EQ(m.mean_error, 0.0);
  EXPECT_EQ(m.max_error, 0.0);
  EXPECT_EQ(m.rmse, 0.0);
  EXPECT_TRUE(std::isinf(m.psnr));
  EXPECT_EQ(m.ssim, 1.0);
  EXPECT_EQ(m.fail_pixels, 0u);
  EXPECT_EQ(m.verdict, Verdict::pass);
}

TEST(Metrics, OneChangedValueGivesDerivedNumbers) {
  // 4×2 RGB = 8 pixels, 24 values, all 0 except b(3,1,B) = 0.5.
  // mean = 0.5/24; RMSE = sqrt(0.25/24); PSNR = 20 log10(1/RMSE) = 10 log10(24/0.25)
  // = 10 log10(96) = 19.8227 dB; 1 of 8 pixels fails the default 1e-6 threshold → 12.5 %.
  const Image a(4, 2, 3, 0.0f);
  Image b = a;
  b.at(3, 1, 2) = 0.5f;
  const Metrics m = compute_metrics(a, b);
  EXPECT_DOUBLE_EQ(m.mean_error, 0.5 / 24.0);
  EXPECT_DOUBLE_EQ(m.rmse, std::sqrt(0.25 / 24.0));
  EXPECT_NEAR(m.psnr, 10.0 * std::log10(96.0), 1e-12);
  EXPECT_NEAR(m.psnr, 19.8227, 1e-4);
  EXPECT_EQ(m.max_error, 0.5);
  EXPECT_EQ(m.max_x, 3);
  EXPECT_EQ(m.max_y, 1);
  EXPECT_EQ(m.max_c, 2);
  EXPECT_EQ(m.pixels, 8u);
  EXPECT_EQ(m.fail_pixels, 1u);
  EXPECT_EQ(m.warn_pixels, 1u);
  EXPECT_DOUBLE_EQ(m.fail_percent, 12.5);
  EXPECT_EQ(m.verdict, Verdict::fail);
}

TEST(Metrics, PixelCountsOnceWhateverHowManyChannelsFail) {
  // All three channels of one pixel differ: still one failing pixel, max at the largest.
  const Image a(3, 3, 3, 0.2f);
  Image b = a;
  b.at(1, 2, 0) = 0.3f;
  b.at(1, 2, 1) = 0.5f;
  b.at(1, 2, 2) = 0.4f;
  const Metrics m = compute_metrics(a, b);
  EXPECT_EQ(m.fail_pixels, 1u);
  EXPECT_EQ(m.max_c, 1);
  EXPECT_NEAR(m.max_error, 0.3, 1e-6);
}

TEST(Metrics, FailPercentAllowsExactlyThatShareOfPixels) {
  // 10×10 = 100 pixels, 3 differ by 0.1 > fail 0.05. idiff fails when nfail > pct/100 · npels:
  // at 3 % the limit is 3 → 3 > 3 is false → not a failure, but 3 > 0 warnings → WARN;
  // at 2.9 % the limit is 2.9 → FAIL.
  const Image a(10, 10, 1, 0.5f);
  Image b = a;
  for (int i = 0; i < 3; ++i) b.at(i, i, 0) = 0.6f;
  Thresholds t;
  t.fail = 0.05;
  t.fail_percent = 3.0;
  EXPECT_EQ(compute_metrics(a, b, t).verdict, Verdict::warn);
  t.warn_percent = 3.0;
  EXPECT_EQ(compute_metrics(a, b, t).verdict, Verdict::pass);
  t.fail_percent = 2.9;
  EXPECT_EQ(compute_metrics(a, b, t).verdict, Verdict::fail);
}

TEST(Metrics, ThresholdIsStrictlyGreaterThan) {
  // Error 0.25 exactly (representable) against a threshold of 0.25: not over it.
  const Image a(2, 1, 1, 0.5f);
  Image b = a;
  b.at(0, 0, 0) = 0.75f;
  Thresholds t;
  t.fail = 0.25;
  t.warn = 0.25;
  EXPECT_EQ(compute_metrics(a, b, t).fail_pixels, 0u);
  t.fail = 0.2499;
  EXPECT_EQ(compute_metrics(a, b, t).fail_pixels, 1u);
}

TEST(Metrics, HardFailTripsOnOneLargeErrorDespitePercentage) {
  const Image a(10, 10, 3, 0.0f);
  Image b = a;
  b.at(5, 5, 0) = 0.9f;
  Thresholds t;
  t.fail_percent = 50;
  t.warn_percent = 50;
  EXPECT_EQ(compute_metrics(a, b, t).verdict, Verdict::pass);
  t.hard_fail = 0.5;
  EXPECT_EQ(compute_metrics(a, b, t).verdict, Verdict::fail);
  t.hard_fail = std::numeric_limits<double>::infinity();
  t.hard_warn = 0.5;
  EXPECT_EQ(compute_metrics(a, b, t).verdict, Verdict::warn);
}

TEST(Metrics, RelativeThresholdMustAlsoBeExceeded) {
  // a = 1.0, b = 0.9: e = 0.1, mean magnitude 0.95, relative error 0.1/0.95 = 0.1053.
  const Image a(1, 1, 1, 1.0f);
  Image b = a;
  b.at(0, 0, 0) = 0.9f;
  Thresholds t;
  t.fail = 0.05;
  t.fail_relative = 0.2;  // 0.1053 < 0.2 → not a failure
  EXPECT_EQ(compute_metrics(a, b, t).fail_pixels, 0u);
  t.fail_relative = 0.1;  // 0.1053 > 0.1 → failure
  EXPECT_EQ(compute_metrics(a, b, t).fail_pixels, 1u);
}

TEST(Metrics, AlphaIsComparedLikeAnyChannel) {
  const Image a(2, 2, 4, 1.0f);
  Image b = a;
  b.at(0, 1, 3) = 0.0f;
  const Metrics m = compute_metrics(a, b);
  EXPECT_EQ(m.max_c, 3);
  EXPECT_EQ(m.max_error, 1.0);
  EXPECT_EQ(m.verdict, Verdict::fail);
}

TEST(Metrics, DifferentSizesThrowNamingBothSizes) {
  try {
    compute_metrics(Image(4, 3, 3), Image(4, 3, 4));
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("4x3x3"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("4x3x4"), std::string::npos) << e.what();
  }
}

TEST(Metrics, MatchingNonFiniteValuesAreEqualMismatchedOnesFail) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  Image a(2, 1, 1, 0.0f), b(2, 1, 1, 0.0f);
  a.at(0, 0, 0) = b.at(0, 0, 0) = nan;
  a.at(1, 0, 0) = b.at(1, 0, 0) = inf;
  Metrics m = compute_metrics(a, b);
  EXPECT_EQ(m.max_error, 0.0);
  EXPECT_EQ(m.verdict, Verdict::pass);
  EXPECT_EQ(m.nonfinite_pixels, 0u);
  b.at(1, 0, 0) = 0.5f;
  m = compute_metrics(a, b);
  EXPECT_TRUE(std::isinf(m.max_error));
  EXPECT_EQ(m.max_x, 1);
  EXPECT_EQ(m.fail_pixels, 1u);
  EXPECT_EQ(m.nonfinite_pixels, 1u);
  // Reported as such, as idiff does (mean and RMS error "inf"), never as a 0 that looks equal.
  EXPECT_TRUE(std::isinf(m.mean_error) && m.mean_error > 0);
  EXPECT_TRUE(std::isinf(m.rmse));
  EXPECT_TRUE(std::isinf(m.psnr) && m.psnr < 0);
  EXPECT_TRUE(std::isnan(m.ssim));
  EXPECT_EQ(m.verdict, Verdict::fail);
}

TEST(Metrics, NanPixelsFailWithNanMetricsWhateverTheThresholds) {
  // Before: FAIL with mean 0 and RMSE 0. (idiff 2.4 even says PASS with "Mean error = nan".)
  const float nan = std::numeric_limits<float>::quiet_NaN();
  Image a(4, 4, 3, 0.25f), b(4, 4, 3, 0.25f);
  b.at(1, 1, 0) = nan;
  b.at(2, 1, 2) = nan;
  Thresholds loose;
  loose.fail = loose.warn = 0.5;
  loose.fail_relative = loose.warn_relative = 2.0;
  const Metrics m = compute_metrics(a, b, loose);
  EXPECT_EQ(m.nonfinite_pixels, 2u);
  EXPECT_EQ(m.fail_pixels, 2u);
  EXPECT_EQ(m.warn_pixels, 2u);
  EXPECT_TRUE(std::isnan(m.mean_error));
  EXPECT_TRUE(std::isnan(m.rmse));
  EXPECT_TRUE(std::isnan(m.psnr));
  EXPECT_TRUE(std::isinf(m.max_error));
  EXPECT_EQ(m.max_x, 1);
  EXPECT_EQ(m.max_y, 1);
  EXPECT_EQ(m.verdict, Verdict::fail);
}

TEST(Metrics, ValidateRejectsNegativeAndOutOfRange) {
  Thresholds t;
  EXPECT_NO_THROW(validate(t));
  t.fail = -1;
  EXPECT_THROW(validate(t), std::invalid_argument);
  t = {};
  t.fail_percent = 101;
  EXPECT_THROW(validate(t), std::invalid_argument);
  t = {};
  t.warn = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(validate(t), std::invalid_argument);
}

}  // namespace
}  // namespace raintrace::compare
