// The lens's softness keeps every channel's light, spreads a point as the Gaussian its contract
// names (scaled with the frame's width), mirrors light back in at the edges, and leaves the
// image alone at 0.
#include "film/softness.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "film/image_sums_test_support.h"

namespace raintrace::film {
namespace {

TEST(Softness, SigmaIsGivenAt1920PixelsAndScalesWithTheWidth) {
  EXPECT_DOUBLE_EQ(softness_sigma_px(1.5, 1920), 1.5);
  EXPECT_DOUBLE_EQ(softness_sigma_px(1.5, 640), 0.5);
  EXPECT_DOUBLE_EQ(softness_sigma_px(0.0, 1280), 0.0);
}

// A single bright pixel in the middle of a 1920-wide frame spreads into the sampled Gaussian:
// the spread's second moment along each axis is Σ i² w_i over the taps |i| <= ⌈3σ⌉ = 5, derived
// here from the contract's definition; it is within 0.5 % of σ² (sampling at whole pixels costs
// ~1e-8 at σ = 1.5, the cut at 3.3σ drops 0.3 % of the variance). The light stays all there, and
// the spread is the same in x and y and in every channel.
TEST(Softness, APointSpreadsIntoTheGaussianAndKeepsItsLight) {
  RgbImage image(1920, 41);
  for (int c = 0; c < 3; ++c) image.at(960, 20, c) = 100.0f * float(c + 1);
  apply_softness(image, 1.5);
  double tap_sum = 0.0, tap_moment = 0.0;
  for (int i = -5; i <= 5; ++i) {
    tap_sum += std::exp(-0.5 * i * i / (1.5 * 1.5));
    tap_moment += i * i * std::exp(-0.5 * i * i / (1.5 * 1.5));
  }
  const double variance = tap_moment / tap_sum;
  EXPECT_NEAR(variance, 1.5 * 1.5, 0.005 * 1.5 * 1.5);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(testing::channel_sum(image, c), 100.0 * (c + 1), 1e-3 * (c + 1));
    double mx = 0.0, my = 0.0, sum = 0.0;
    for (int y = 0; y < image.height; ++y) {
      for (int x = 900; x < 1020; ++x) {
        const double v = image.at(x, y, c);
        sum += v;
        mx += v * (x - 960) * (x - 960);
        my += v * (y - 20) * (y - 20);
      }
    }
    EXPECT_NEAR(mx / sum, variance, 1e-5) << "channel " << c;
    EXPECT_NEAR(my / sum, variance, 1e-5) << "channel " << c;
  }
  EXPECT_FLOAT_EQ(image.at(961, 20, 0), image.at(960, 21, 0));
  EXPECT_FLOAT_EQ(image.at(959, 20, 0), image.at(961, 20, 0));
}

// Light next to an edge is reflected back in: a bright column on the first pixel keeps its sum,
// and so do images smaller than the kernel (a 1×1 image is unchanged; a 2×3 one keeps its light).
TEST(Softness, EdgesMirrorTheLightBackIn) {
  RgbImage edge(1920, 8);
  for (int y = 0; y < 8; ++y) edge.at(0, y, 1) = 50.0f;
  apply_softness(edge, 4.0);
  EXPECT_NEAR(testing::channel_sum(edge, 1), 8 * 50.0, 1e-3);
  EXPECT_GT(edge.at(5, 3, 1), 0.0f);

  RgbImage one(1, 1, 0.7f);
  apply_softness(one, 4.0);  // σ = 4/1920 px: below the negligible 0.05 anyway
  EXPECT_EQ(one.at(0, 0, 0), 0.7f);

  RgbImage tiny(2, 3);
  tiny.at(1, 2, 2) = 9.0f;
  const double sigma = softness_sigma_px(4.0, 2);
  ASSERT_LT(sigma, 0.05);  // a 2-pixel-wide frame: far too small to blur at all
  apply_softness(tiny, 4.0);
  EXPECT_EQ(tiny.at(1, 2, 2), 9.0f);
}

TEST(Softness, ZeroIsANoOpAndRangeIsChecked) {
  RgbImage image(64, 64);
  image.at(10, 10, 0) = 5.0f;
  const RgbImage before = image;
  apply_softness(image, 0.0);
  EXPECT_EQ(image.pixels, before.pixels);
  EXPECT_THROW(apply_softness(image, 4.5), std::invalid_argument);
  EXPECT_THROW(apply_softness(image, -0.1), std::invalid_argument);
}

}  // namespace
}  // namespace raintrace::film
