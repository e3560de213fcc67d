// The pyramid steps conserve energy at every size (odd, tiny, kernel wider than the image).
#include "film/pyramid.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <utility>

namespace raintrace::film {
namespace {

/// A reproducible HDR-like image: values from a small integer hash, a few far above 1.
RgbImage test_image(int w, int h, std::uint32_t salt = 1) {
  RgbImage image(w, h);
  std::uint32_t state = 2463534242u ^ salt;
  for (float& v : image.pixels) {
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    v = float(state % 1000) / 1000.0f;
    if (state % 97 == 0) v *= 500.0f;  // hot pixels, like lamp bulbs
  }
  return image;
}

double channel_sum(const RgbImage& image, int c) {
  double sum = 0.0;
  for (std::size_t i = 0; i < image.pixel_count(); ++i) sum += image.pixels[i * 3 + c];
  return sum;
}

// Every output value is a sum of at most 16 float products, so its relative rounding error is
// below 16 · 2⁻²⁴ ≈ 1e-6; the channel sums (taken in double) inherit that bound.
constexpr double kRelativeTolerance = 1e-6;

const std::pair<int, int> kSizes[] = {{1, 1}, {1, 7},  {7, 1},   {2, 2},  {5, 3},
                                      {8, 6}, {13, 9}, {64, 36}, {45, 23}};

TEST(Pyramid, DownsampleKeepsEnergyAtAnySize) {
  for (auto [w, h] : kSizes) {
    const RgbImage in = test_image(w, h);
    const RgbImage out = downsample_half(in);
    EXPECT_EQ(out.width, (w + 1) / 2);
    EXPECT_EQ(out.height, (h + 1) / 2);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(4.0 * channel_sum(out, c), channel_sum(in, c),
                  kRelativeTolerance * channel_sum(in, c))
          << w << "x" << h << " channel " << c;
    }
  }
}

TEST(Pyramid, UpsampleKeepsEnergyForEvenAndOddTargets) {
  for (auto [w, h] : kSizes) {
    const RgbImage coarse = test_image(w, h, 7);
    for (int odd_w = 0; odd_w < 2; ++odd_w) {
      for (int odd_h = 0; odd_h < 2; ++odd_h) {
        const int tw = 2 * w - odd_w;
        const int th = 2 * h - odd_h;
        const RgbImage fine = upsample_double(coarse, tw, th);
        ASSERT_EQ(fine.width, tw);
        ASSERT_EQ(fine.height, th);
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(channel_sum(fine, c), 4.0 * channel_sum(coarse, c),
                      kRelativeTolerance * 4.0 * channel_sum(coarse, c))
              << w << "x" << h << " → " << tw << "x" << th;
        }
      }
    }
  }
}

TEST(Pyramid, UpsampleOfAConstantIsThatConstant) {
  // Even targets: bilinear weights sum to 1 everywhere, clamped edges included.
  const RgbImage coarse(6, 4, 0.25f);
  const RgbImage fine = upsample_double(coarse, 12, 8);
  for (float v : fine.pixels) EXPECT_FLOAT_EQ(v, 0.25f);
}

TEST(Pyramid, UpsampleRejectsSizesThatAreNotDouble) {
  const RgbImage coarse(6, 4);
  EXPECT_THROW(upsample_double(coarse, 13, 8), std::invalid_argument);
  EXPECT_THROW(upsample_double(coarse, 12, 6), std::invalid_argument);
}

TEST(Pyramid, BlurKeepsEnergyWithMirroredEdges) {
  for (auto [w, h] : kSizes) {
    const RgbImage in = test_image(w, h, 3);
    const RgbImage out = blur_binomial5(in);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(channel_sum(out, c), channel_sum(in, c), kRelativeTolerance * channel_sum(in, c))
          << w << "x" << h;
    }
  }
}

TEST(Pyramid, BlurSpreadsAPointWithVarianceOnePixelPerAxis) {
  // [1 4 6 4 1]/16 has variance (1·2² + 4·1² + 4·1² + 1·2²) / 16 = 1 along each axis.
  RgbImage in(11, 11);
  in.at(5, 5, 0) = 1.0f;
  const RgbImage out = blur_binomial5(in);
  double vx = 0.0, vy = 0.0;
  for (int y = 0; y < 11; ++y) {
    for (int x = 0; x < 11; ++x) {
      vx += out.at(x, y, 0) * double((x - 5) * (x - 5));
      vy += out.at(x, y, 0) * double((y - 5) * (y - 5));
    }
  }
  EXPECT_NEAR(vx, 1.0, 1e-6);
  EXPECT_NEAR(vy, 1.0, 1e-6);
  EXPECT_NEAR(out.at(5, 5, 0), 36.0 / 256.0, 1e-7);
}

TEST(Pyramid, BlurOfACornerPointReflectsLightBackIn) {
  // A point in the corner: the taps that fall off the edge land back on the image, mirrored.
  RgbImage in(4, 4);
  in.at(0, 0, 1) = 1.0f;
  const RgbImage out = blur_binomial5(in);
  // Along one axis the corner keeps 6/16 + 4/16 (its mirror image at −1) = 10/16.
  EXPECT_NEAR(out.at(0, 0, 1), (10.0 / 16.0) * (10.0 / 16.0), 1e-7);
  EXPECT_NEAR(channel_sum(out, 1), 1.0, 1e-6);
}

}  // namespace
}  // namespace raintrace::film
