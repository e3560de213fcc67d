// White balance against published colorimetry: the Planckian locus through CIE illuminant A,
// and a light of the balance temperature developing as grey of its own luminance.
#include "film/white_balance.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace raintrace::film {
namespace {

double luminance(const std::array<double, 3>& rgb) {
  return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}

TEST(WhiteBalance, TheLocusPassesThroughIlluminantA) {
  // CIE 15:2004: illuminant A, a blackbody at 2856 K, is at x = 0.44757, y = 0.40745.
  const auto [x, y] = blackbody_chromaticity(2856.0);
  EXPECT_NEAR(x, 0.44757, 0.001);
  EXPECT_NEAR(y, 0.40745, 0.001);
}

TEST(WhiteBalance, AHotBlackbodyIsNearlyTheDaylightWhiteOfSrgb) {
  // D65 (x 0.3127, y 0.3290) lies a little off the locus, near 6500 K: sRGB's white is about
  // (1, 1, 1) there, and the warm lamps of a street are far from it.
  const std::array<double, 3> near_white = blackbody_rgb(6500.0);
  for (double c : near_white) EXPECT_NEAR(c, 1.0, 0.06);
  const std::array<double, 3> lamp = blackbody_rgb(3000.0);
  EXPECT_GT(lamp[0], 1.7);
  EXPECT_LT(lamp[2], 0.3);
}

TEST(WhiteBalance, ColoursHaveLuminanceOneAndWarmerMeansRedder) {
  double previous_ratio = 0.0;
  for (double kelvin : {20000.0, 10000.0, 6500.0, 4000.0, 3000.0, 2000.0}) {
    const std::array<double, 3> rgb = blackbody_rgb(kelvin);
    EXPECT_NEAR(luminance(rgb), 1.0, 1e-12) << kelvin;
    const double ratio = rgb[0] / rgb[2];
    EXPECT_GT(ratio, previous_ratio) << kelvin;
    previous_ratio = ratio;
  }
}

TEST(WhiteBalance, LightOfTheBalanceTemperatureDevelopsGreyWithItsLuminance) {
  for (double kelvin : {2000.0, 3200.0, 5600.0, 20000.0}) {
    const std::array<double, 3> light = blackbody_rgb(kelvin);
    RgbImage image(2, 1);
    for (int c = 0; c < 3; ++c) {
      image.at(0, 0, c) = float(0.25 * light[c]);
      image.at(1, 0, c) = float(4.0 * light[c]);
    }
    apply_white_balance(image, kelvin);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(image.at(0, 0, c), 0.25, 1e-5) << kelvin;
      EXPECT_NEAR(image.at(1, 0, c), 4.0, 1e-4) << kelvin;
    }
  }
}

TEST(WhiteBalance, OtherLightsKeepTheirHueAroundTheBalance) {
  // Balanced for 3500 K: a 3000 K lamp stays warm, a 4000 K one turns cool, a 2000 K sodium-like
  // one stays orange.
  const auto balanced = [](double kelvin) {
    const std::array<double, 3> light = blackbody_rgb(kelvin);
    RgbImage image(1, 1);
    for (int c = 0; c < 3; ++c) image.at(0, 0, c) = float(light[c]);
    apply_white_balance(image, 3500.0);
    return image;
  };
  const RgbImage warm = balanced(3000.0);
  EXPECT_GT(warm.at(0, 0, 0), warm.at(0, 0, 2));
  const RgbImage cool = balanced(4000.0);
  EXPECT_LT(cool.at(0, 0, 0), cool.at(0, 0, 2));
  const RgbImage sodium = balanced(2000.0);
  EXPECT_GT(sodium.at(0, 0, 0), 10.0 * sodium.at(0, 0, 2));
}

TEST(WhiteBalance, ZeroLeavesTheFrameAsTraced) {
  RgbImage image(3, 2, 0.3f);
  image.at(1, 1, 2) = 7.0f;
  const RgbImage before = image;
  apply_white_balance(image, 0.0);
  EXPECT_EQ(image.pixels, before.pixels);
}

TEST(WhiteBalance, RefusesTemperaturesOutsideItsRange) {
  RgbImage image(1, 1, 1.0f);
  for (double kelvin : {-1.0, 1000.0, 1999.0, 20001.0}) {
    EXPECT_THROW(apply_white_balance(image, kelvin), std::invalid_argument) << kelvin;
  }
  EXPECT_THROW(blackbody_rgb(1500.0), std::invalid_argument);
}

}  // namespace
}  // namespace raintrace::film
