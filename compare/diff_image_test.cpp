// The heat map's colours, scale and layout on hand-made differences.
#include "compare/diff_image.h"

#include <gtest/gtest.h>

namespace raintrace::compare {
namespace {

TEST(DiffImage, AutoFullScaleRoundsUpToOneTwoFive) {
  EXPECT_DOUBLE_EQ(auto_full_scale(0.0), 1.0 / 255.0);    // identical: one 8-bit step
  EXPECT_DOUBLE_EQ(auto_full_scale(0.001), 1.0 / 255.0);  // below one step
  EXPECT_DOUBLE_EQ(auto_full_scale(0.013), 0.02);
  EXPECT_DOUBLE_EQ(auto_full_scale(0.2), 0.2);
  EXPECT_DOUBLE_EQ(auto_full_scale(0.31), 0.5);
  EXPECT_DOUBLE_EQ(auto_full_scale(0.7), 1.0);
}

TEST(DiffImage, ColourRampRunsBlackRedYellowWhite) {
  float rgb[3];
  heat_colour(0.0, rgb);
  EXPECT_EQ(rgb[0] + rgb[1] + rgb[2], 0.0f);
  heat_colour(0.5, rgb);  // halfway between red (1/3) and yellow (2/3): (1, 0.5, 0)
  EXPECT_FLOAT_EQ(rgb[0], 1.0f);
  EXPECT_FLOAT_EQ(rgb[1], 0.5f);
  EXPECT_FLOAT_EQ(rgb[2], 0.0f);
  heat_colour(1.0, rgb);
  EXPECT_EQ(rgb[0] + rgb[1] + rgb[2], 3.0f);
}

TEST(DiffImage, ErrorMapsToColourByFullScaleAndBarIsAppended) {
  // 40×10 RGBA; pixel (1,1) differs by 0.1 in alpha only, pixel (2,1) by 0.05 in green.
  // Full scale 0.1: (1,1) → t = 1 → white; (2,1) → t = 0.5 → (1, 0.5, 0); the rest black.
  const Image a(40, 10, 4, 0.5f);
  Image b = a;
  b.at(1, 1, 3) = 0.6f;
  b.at(2, 1, 1) = 0.45f;
  const Image heat = difference_heatmap(a, b, 0.1);
  ASSERT_EQ(heat.width, 40);
  ASSERT_EQ(heat.height, 10 + scale_bar_height(40));
  ASSERT_EQ(heat.channels, 3);
  EXPECT_NEAR(heat.at(1, 1, 1), 1.0f, 1e-5);
  EXPECT_NEAR(heat.at(1, 1, 2), 1.0f, 1e-5);
  EXPECT_NEAR(heat.at(2, 1, 0), 1.0f, 1e-5);
  EXPECT_NEAR(heat.at(2, 1, 1), 0.5f, 1e-5);
  EXPECT_EQ(heat.at(0, 0, 0), 0.0f);
  // The ramp starts black at its left end and ends white at its right end (row 2 of the bar).
  const int ramp_y = 10 + 3;
  EXPECT_EQ(heat.at(2, ramp_y, 0), 0.0f);
  EXPECT_EQ(heat.at(40 - 3, ramp_y, 2), 1.0f);
}

TEST(DiffImage, LabelsAreDrawnUnderTheRamp) {
  // The "0" label sits at the left margin under the ramp: some of its pixels are white.
  const Image a(200, 20, 3, 0.0f);
  const Image heat = difference_heatmap(a, a);
  int white = 0;
  for (int y = 20 + 8; y < 20 + 13; ++y)
    for (int x = 0; x < 10; ++x) white += heat.at(x, y, 0) == 1.0f && heat.at(x, y, 2) == 1.0f;
  EXPECT_GT(white, 3);
  // Identical images: the map itself is all black.
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 200; ++x) ASSERT_EQ(heat.at(x, y, 0), 0.0f);
}

}  // namespace
}  // namespace raintrace::compare
