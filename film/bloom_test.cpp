// Bloom conserves energy, spreads a point light into the documented 1/r² profile, and covers the
// same part of the frame at every resolution.
#include "film/bloom.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "film/image_sums_test_support.h"

namespace raintrace::film {
namespace {

/// A dark night frame: a dim gradient with a few lamps 1000× brighter, one in a corner and one
/// on the last column (where odd pyramid levels pad and fold).
RgbImage night_frame(int w, int h) {
  RgbImage image(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      image.at(x, y, 0) = 0.01f + 0.02f * float(x) / float(w);
      image.at(x, y, 1) = 0.015f;
      image.at(x, y, 2) = 0.02f * float(y) / float(h);
    }
  }
  for (auto [x, y] : {std::pair{0, 0}, std::pair{w - 1, h / 2}, std::pair{w / 3, h / 4}}) {
    image.at(x, y, 0) = 800.0f;
    image.at(x, y, 1) = 600.0f;
    image.at(x, y, 2) = 300.0f;
  }
  return image;
}

/// Fraction of a point's light (channel `c`) within radius r of (cx, cy), counting the pixels
/// whose centres lie within r.
double encircled(const RgbImage& image, int cx, int cy, double r, double total, int c = 0) {
  double sum = 0.0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (std::hypot(x - cx, y - cy) <= r) sum += image.at(x, y, c);
    }
  }
  return sum / total;
}

/// The documented profile's encircled energy at radius r, for strength k: the unscattered part
/// plus each level's 2-D Gaussian, 1 − exp(−r² / 2σ²).
double documented_encircled(const std::vector<BloomLevel>& levels, double k, double r) {
  double ee = 1.0;
  for (const BloomLevel& level : levels) {
    ee -= k * level.weight * std::exp(-r * r / (2.0 * level.sigma_px * level.sigma_px));
  }
  return ee;
}

TEST(Bloom, LevelsSpanEightOctavesFromTheReferenceWidth) {
  const std::vector<BloomLevel> at_1280 = bloom_levels(1280);
  ASSERT_EQ(at_1280.size(), 8u);
  EXPECT_EQ(at_1280.front().level, 0);
  EXPECT_EQ(at_1280.back().level, 7);
  EXPECT_DOUBLE_EQ(at_1280.front().sigma_px, 1.0);
  // σ_7² = 4⁷ + (4⁷ − 1) · 11/36 = 21390.1 → σ_7 = 146.25 px, a ninth of 1280.
  EXPECT_NEAR(at_1280.back().sigma_px, 146.25, 0.01);
  for (const BloomLevel& level : at_1280) EXPECT_DOUBLE_EQ(level.weight, 1.0 / 8.0);

  // Half the width: one level finer than a pixel is dropped, the rest move down by one.
  const std::vector<BloomLevel> at_640 = bloom_levels(640);
  ASSERT_EQ(at_640.size(), 7u);
  EXPECT_EQ(at_640.back().level, 6);
  // 320×240 (the Table 1 preview): levels 0–5, three quarters of the glare.
  EXPECT_EQ(bloom_levels(320).size(), 6u);
  // Twice the width: levels 1–8.
  EXPECT_EQ(bloom_levels(2560).front().level, 1);
  EXPECT_EQ(bloom_levels(2560).back().level, 8);
}

TEST(Bloom, ZeroStrengthLeavesTheImageAlone) {
  const RgbImage in = night_frame(64, 36);
  EXPECT_EQ(bloom(in, 0.0).pixels, in.pixels);
}

TEST(Bloom, RejectsStrengthOutsideZeroToOne) {
  const RgbImage in(8, 8);
  EXPECT_THROW(bloom(in, -0.1), std::invalid_argument);
  EXPECT_THROW(bloom(in, 1.5), std::invalid_argument);
  EXPECT_THROW(bloom(in, std::nan("")), std::invalid_argument);
}

TEST(Bloom, ConservesEveryChannelsEnergyWithLampsAtTheEdges) {
  // 1280×720 reaches an odd level (45 → 23 rows) and 333×187 is odd from the start. Tolerance:
  // each pyramid step keeps a channel's sum to 1e-6 relative (pyramid_test); bloom chains at
  // most 8 downsamples, 8 blurs, 8 upsamples and a weighted sum, so 3e-5 of the sum bounds it.
  for (auto [w, h] : {std::pair{1280, 720}, std::pair{333, 187}, std::pair{17, 5}}) {
    const RgbImage in = night_frame(w, h);
    for (double k : {0.04, 1.0}) {
      const RgbImage out = bloom(in, k);
      for (int c = 0; c < 3; ++c) {
        const double before = testing::channel_sum(in, c);
        EXPECT_NEAR(testing::channel_sum(out, c), before, 3e-5 * before)
            << w << "x" << h << " k=" << k << " channel " << c;
      }
    }
  }
}

// The pyramid's level kernels are compositions of box, binomial and tent filters rather than
// exact Gaussians, and a point's position on each coarse grid shifts its light by up to half a
// coarse pixel. Measured at this position the encircled energy differs from the Gaussian formula
// by at most 0.022 of the total between r = 2 and 512 px; r = 1 is left out because five whole
// pixels (reaching 1.5 px) are not a disc of radius 1.
constexpr double kProfileTolerance = 0.03;

TEST(Bloom, SpreadsAPointLightIntoTheDocumentedProfile) {
  // A point far from the edges of a 1280-wide frame, strength 1: all its light is scattered.
  const int size = 1280;
  RgbImage in(size, size);
  const int c = size / 2;
  in.at(c, c, 0) = 1.0f;
  const RgbImage out = bloom(in, 1.0);
  const std::vector<BloomLevel> levels = bloom_levels(size);
  for (double r : {2.0, 4.0, 8.0, 16.0, 32.0, 64.0, 128.0, 256.0, 512.0}) {
    EXPECT_NEAR(encircled(out, c, c, r, 1.0), documented_encircled(levels, 1.0, r),
                kProfileTolerance)
        << "radius " << r;
  }
  // 1/r²: each octave of radius holds about the same share, 1/8 (between 4 and 128 px, where
  // no level is cut off by the pixel or the frame).
  for (double r = 4.0; r < 128.0; r *= 2.0) {
    const double octave = encircled(out, c, c, 2.0 * r, 1.0) - encircled(out, c, c, r, 1.0);
    EXPECT_NEAR(octave, 1.0 / 8.0, 0.01) << "between " << r << " and " << 2 * r;
  }
}

TEST(Bloom, GlareCoversTheSamePartOfTheFrameAtHalfTheWidth) {
  // A lamp at the centre of a square 1280 and a square 640 frame: at 640 every level is one
  // finer, so the encircled energy at r matches 1280's at 2r; 1280's finest level (σ = 1 px)
  // is inside both radii from 2r = 4 on.
  RgbImage big(1280, 1280), small(640, 640);
  big.at(640, 640, 1) = 1.0f;
  small.at(320, 320, 1) = 1.0f;
  const RgbImage big_out = bloom(big, 0.5);
  const RgbImage small_out = bloom(small, 0.5);
  for (double r : {2.0, 4.0, 8.0, 16.0, 32.0, 64.0, 128.0, 256.0}) {
    EXPECT_NEAR(encircled(small_out, 320, 320, r, 1.0, 1),
                encircled(big_out, 640, 640, 2.0 * r, 1.0, 1), kProfileTolerance)
        << "radius " << r << " at 640 vs " << 2 * r << " at 1280";
  }
}

}  // namespace
}  // namespace raintrace::film
