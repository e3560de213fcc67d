// Vignetting follows the cos⁴ law of a pinhole camera with the scene's field of view.
#include "film/vignette.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace raintrace::film {
namespace {

/// cos⁴ of the angle off the axis, from the angle itself (atan, cos), independent of the
/// implementation's cos² = f² / (f² + r²).
double cos4_of_pixel(int x, int y, int w, int h, double fov_deg) {
  const double f = 0.5 * w / std::tan(fov_deg * std::numbers::pi / 360.0);
  const double r = std::hypot(x + 0.5 - 0.5 * w, y + 0.5 - 0.5 * h);
  return std::pow(std::cos(std::atan(r / f)), 4.0);
}

TEST(Vignette, FullStrengthIsTheCosFourthLaw) {
  const int w = 64, h = 36;
  RgbImage image(w, h, 1.0f);
  apply_vignette(image, 1.0, 60.0);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(image.at(x, y, c), cos4_of_pixel(x, y, w, h, 60.0), 1e-6) << x << "," << y;
      }
    }
  }
}

TEST(Vignette, CornersOfA60DegreeWideFrameLoseAStop) {
  // 16:9 at 60°: the corner is at r = √(0.5² + 0.28125²)·w, f = 0.866·w, tan θ = 0.6624,
  // cos⁴θ = 0.483 (−1.05 stops), as the header says.
  RgbImage image(1280, 720, 1.0f);
  apply_vignette(image, 1.0, 60.0);
  EXPECT_NEAR(image.at(0, 0, 0), 0.483, 0.002);
  EXPECT_NEAR(image.at(1279, 719, 2), 0.483, 0.002);
  // The four pixels around the centre are within half a pixel of the axis.
  EXPECT_NEAR(image.at(640, 360, 1), 1.0, 1e-6);
}

TEST(Vignette, StrengthBlendsTowardsNoFalloff) {
  const int w = 40, h = 30;
  RgbImage half(w, h, 2.0f), none(w, h, 2.0f);
  apply_vignette(half, 0.5, 90.0);
  apply_vignette(none, 0.0, 90.0);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      EXPECT_NEAR(half.at(x, y, 0), 2.0 * (0.5 + 0.5 * cos4_of_pixel(x, y, w, h, 90.0)), 1e-6);
      EXPECT_EQ(none.at(x, y, 0), 2.0f);
    }
  }
}

TEST(Vignette, IsSymmetricAboutTheCentre) {
  const int w = 33, h = 20;
  RgbImage image(w, h, 1.0f);
  apply_vignette(image, 1.0, 75.0);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      EXPECT_FLOAT_EQ(image.at(x, y, 0), image.at(w - 1 - x, y, 0));
      EXPECT_FLOAT_EQ(image.at(x, y, 0), image.at(x, h - 1 - y, 0));
    }
  }
}

TEST(Vignette, RejectsStrengthOrFieldOfViewOutOfRange) {
  RgbImage image(4, 4, 1.0f);
  EXPECT_THROW(apply_vignette(image, 1.1, 60.0), std::invalid_argument);
  EXPECT_THROW(apply_vignette(image, -0.1, 60.0), std::invalid_argument);
  EXPECT_THROW(apply_vignette(image, 0.5, 0.0), std::invalid_argument);
  EXPECT_THROW(apply_vignette(image, 0.5, 180.0), std::invalid_argument);
}

}  // namespace
}  // namespace raintrace::film
