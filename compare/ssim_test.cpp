// SSIM against the closed form for flat images and against a direct, unoptimised evaluation of
// Wang et al.'s formula window by window.
#include "compare/ssim.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

namespace raintrace::compare {
namespace {

constexpr double kC1 = 0.0001, kC2 = 0.0009;  // (0.01·1)², (0.03·1)²

Image noise(int w, int h, int c, std::uint32_t seed) {
  Image img(w, h, c);
  for (auto& v : img.pixels) {
    seed = seed * 1664525u + 1013904223u;  // LCG: deterministic test data
    v = float(seed >> 8) / float(1u << 24);
  }
  return img;
}

// Direct evaluation: for each valid centre, Gaussian-weighted statistics over the 11×11 window.
double brute_force_ssim(const Image& a, const Image& b) {
  const auto ya = luminance(a), yb = luminance(b);
  double g[11][11], sum = 0;
  for (int i = 0; i < 11; ++i)
    for (int j = 0; j < 11; ++j)
      sum += g[i][j] = std::exp(-((i - 5) * (i - 5) + (j - 5) * (j - 5)) / 4.5);
  double total = 0;
  int count = 0;
  for (int cy = 5; cy < a.height - 5; ++cy) {
    for (int cx = 5; cx < a.width - 5; ++cx) {
      double ma = 0, mb = 0, saa = 0, sbb = 0, sab = 0;
      for (int i = 0; i < 11; ++i)
        for (int j = 0; j < 11; ++j) {
          const double w = g[i][j] / sum;
          const std::size_t k = std::size_t(cy + i - 5) * a.width + cx + j - 5;
          ma += w * ya[k];
          mb += w * yb[k];
        }
      for (int i = 0; i < 11; ++i)
        for (int j = 0; j < 11; ++j) {
          const double w = g[i][j] / sum;
          const std::size_t k = std::size_t(cy + i - 5) * a.width + cx + j - 5;
          saa += w * (ya[k] - ma) * (ya[k] - ma);
          sbb += w * (yb[k] - mb) * (yb[k] - mb);
          sab += w * (ya[k] - ma) * (yb[k] - mb);
        }
      total +=
          (2 * ma * mb + kC1) * (2 * sab + kC2) / ((ma * ma + mb * mb + kC1) * (saa + sbb + kC2));
      ++count;
    }
  }
  return total / count;
}

TEST(Ssim, IdenticalImagesGiveExactlyOne) {
  const Image a = noise(32, 24, 3, 7);
  EXPECT_EQ(ssim(a, a), 1.0);
}

TEST(Ssim, FlatImagesFollowTheLuminanceTerm) {
  // Flat images have σ = 0, so the contrast-structure term is C2/C2 = 1 and
  // SSIM = (2·0.5·0.25 + C1) / (0.5² + 0.25² + C1) = 0.2501 / 0.3126 = 0.800064.
  const Image a(16, 16, 1, 0.5f), b(16, 16, 1, 0.25f);
  EXPECT_NEAR(ssim(a, b), (2 * 0.5 * 0.25 + kC1) / (0.25 + 0.0625 + kC1), 1e-12);
  EXPECT_NEAR(ssim(a, b), 0.800064, 1e-6);
}

TEST(Ssim, SmallImagesUseTheClippedWindow) {
  // 5×4 is under 11 pixels: every pixel is a centre; flat images still give the closed form.
  const Image a(5, 4, 3, 0.8f), b(5, 4, 3, 0.4f);
  EXPECT_NEAR(ssim(a, b), (2 * 0.8 * 0.4 + kC1) / (0.64 + 0.16 + kC1), 1e-6);
}

TEST(Ssim, MatchesDirectWindowEvaluation) {
  const Image a = noise(23, 17, 3, 1);
  Image b = a;
  const Image n = noise(23, 17, 3, 99);
  for (std::size_t i = 0; i < b.pixels.size(); ++i)
    b.pixels[i] = 0.7f * b.pixels[i] + 0.3f * n.pixels[i];
  const double expected = brute_force_ssim(a, b);
  EXPECT_NEAR(ssim(a, b), expected, 1e-9);
  EXPECT_LT(expected, 0.99);  // a real difference, not a trivial 1
  EXPECT_GT(expected, 0.3);
}

TEST(Ssim, InvertedContrastIsNegative) {
  // b = 1 − a: σab = −σa², so the structure term is negative for a textured image.
  const Image a = noise(20, 20, 1, 5);
  Image b = a;
  for (auto& v : b.pixels) v = 1.0f - v;
  EXPECT_LT(ssim(a, b), 0.0);
}

TEST(Ssim, LuminanceUsesRec709Weights) {
  Image img(3, 1, 3, 0.0f);
  img.at(0, 0, 0) = 1.0f;
  img.at(1, 0, 1) = 1.0f;
  img.at(2, 0, 2) = 1.0f;
  const auto y = luminance(img);
  EXPECT_FLOAT_EQ(y[0], 0.2126f);
  EXPECT_FLOAT_EQ(y[1], 0.7152f);
  EXPECT_FLOAT_EQ(y[2], 0.0722f);
}

}  // namespace
}  // namespace raintrace::compare
