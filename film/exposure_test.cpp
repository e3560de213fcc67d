// Exposure scales light by powers of two and turns what a renderer should never write (NaN,
// negative, infinite) into values bloom can safely spread.
#include "film/exposure.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace raintrace::film {
namespace {

TEST(Exposure, EachStopDoublesTheLight) {
  RgbImage image(2, 1);
  image.pixels = {0.18f, 1.0f, 8.0f, 0.0f, 0.5f, 100.0f};
  RgbImage plus_one = image, minus_two = image, zero = image;
  apply_exposure(plus_one, 1.0);
  apply_exposure(minus_two, -2.0);
  apply_exposure(zero, 0.0);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    EXPECT_FLOAT_EQ(plus_one.pixels[i], 2.0f * image.pixels[i]);
    EXPECT_FLOAT_EQ(minus_two.pixels[i], 0.25f * image.pixels[i]);
    EXPECT_EQ(zero.pixels[i], image.pixels[i]);
  }
}

TEST(Exposure, NanAndNegativeBecomeBlackInfinityTheLargestHalf) {
  RgbImage image(2, 1);
  image.pixels = {std::numeric_limits<float>::quiet_NaN(),
                  -3.0f,
                  std::numeric_limits<float>::infinity(),
                  1e9f,
                  65504.0f,
                  2.0f};
  apply_exposure(image, -1.0);
  EXPECT_EQ(image.pixels[0], 0.0f);
  EXPECT_EQ(image.pixels[1], 0.0f);
  EXPECT_EQ(image.pixels[2], kHalfMax / 2);
  EXPECT_EQ(image.pixels[3], kHalfMax / 2);
  EXPECT_EQ(image.pixels[4], kHalfMax / 2);
  EXPECT_EQ(image.pixels[5], 1.0f);
}

TEST(Exposure, RejectsStopsOutOfRange) {
  RgbImage image(1, 1);
  EXPECT_THROW(apply_exposure(image, 16.5), std::invalid_argument);
  EXPECT_THROW(apply_exposure(image, -17.0), std::invalid_argument);
  EXPECT_THROW(apply_exposure(image, std::nan("")), std::invalid_argument);
  EXPECT_NO_THROW(apply_exposure(image, 16.0));
}

}  // namespace
}  // namespace raintrace::film
