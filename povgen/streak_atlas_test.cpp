// Streak atlas: rows scale the opacity by 2^(1/8), every column's profile carries exactly the
// drop's area of coverage, the cell lookup and the 16-bit PNG file.
#include "povgen/streak_atlas.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>

#include "povgen/test_support/atlas_texels.h"
#include "tests/support/command.h"

namespace raintrace::povgen {
namespace {

using test_support::atlas_alpha_at;
using test_support::atlas_cell_mean;

TEST(StreakAtlas, RowsScaleTheOpacityByAnEighthOfAHalving) {
  const StreakAtlasLayout layout;
  const auto px = streak_atlas_pixels(layout);
  ASSERT_EQ(px.size(), static_cast<std::size_t>(layout.width()) * layout.height() * 2);
  EXPECT_DOUBLE_EQ(layout.row_opacity(8), 0.5);
  EXPECT_NEAR(layout.faintest_opacity(), std::exp2(-13.0), 1e-15);
  // Every cell is its column's profile times its row's opacity (to 16-bit rounding).
  const int long_column = layout.motions - 1;
  const double top =
      atlas_alpha_at(px, layout, 0, long_column, layout.cell_width / 2, layout.cell_height / 2);
  EXPECT_GT(top, 0.95);
  for (const int row : {3, 8, 40, 96}) {
    EXPECT_NEAR(
        atlas_alpha_at(px, layout, row, long_column, layout.cell_width / 2, layout.cell_height / 2),
        top * layout.row_opacity(row), 0.6 / 65535.0)
        << row;
  }
}

TEST(StreakAtlas, EveryColumnCarriesTheDropsAreaOfCoverage) {
  // A quad of the drop's diameter D (resolved) and length (1 + motion)·D, at the middle's
  // opacity min(1, 1/motion), must integrate to the disc's πD²/4 — the same for every motion
  // (Garg & Nayar: the exposure spreads a drop's light, it adds none). A sub-pixel quad of any
  // width w at opacity × D/w carries the same. In cell units: mean × gain × middle ×
  // (1 + motion) = π/4, for the default cells as POV-Ray filters them. The gains stay close
  // to the profile's own peak: within 25 %.
  StreakAtlasLayout layout;
  layout.opacity_levels = 1;
  const auto px = streak_atlas_pixels(layout);
  for (int column = 0; column < layout.columns(); ++column) {
    const double motion = streak_atlas_motion(layout, column % layout.motions);
    const double middle = motion > 1.0 ? 1.0 / motion : 1.0;
    EXPECT_NEAR(atlas_cell_mean(px, layout, 0, column) * streak_atlas_column_gain(layout, column) *
                    middle * (1.0 + motion),
                std::numbers::pi / 4, 0.001)
        << "column " << column << ", motion " << motion;
    EXPECT_GT(streak_atlas_column_gain(layout, column), 0.75) << column;
    EXPECT_LT(streak_atlas_column_gain(layout, column), 1.25) << column;
  }
}

TEST(StreakAtlas, ResolvedStreaksShowTheDropsOutlineSubPixelOnesAreFlatAcross) {
  const StreakAtlasLayout layout;
  const auto px = streak_atlas_pixels(layout);
  const int middle = layout.cell_height / 2;
  // Motion 2: resolved is clear at its rim, full on its axis.
  const int resolved = 3;  // motion 2
  EXPECT_NEAR(streak_atlas_motion(layout, resolved), 2.0, 0.0);
  EXPECT_GT(atlas_alpha_at(px, layout, 0, resolved, layout.cell_width / 2, middle), 0.9);
  EXPECT_LT(atlas_alpha_at(px, layout, 0, resolved, 0, middle), 0.5);
  // Sub-pixel: the same across the cell, its peak in the middle of the streak.
  const int sub_pixel = resolved + layout.motions;
  const double centre = atlas_alpha_at(px, layout, 0, sub_pixel, layout.cell_width / 2, middle);
  EXPECT_NEAR(centre, 1.0, 1e-4);
  EXPECT_NEAR(atlas_alpha_at(px, layout, 0, sub_pixel, 0, middle), centre, 1e-9);
  // Both end clear: nothing is drawn before the drop arrives or after it has gone.
  EXPECT_LT(atlas_alpha_at(px, layout, 0, sub_pixel, 0, 0), 0.05);
  EXPECT_LT(atlas_alpha_at(px, layout, 0, sub_pixel, 0, layout.cell_height - 1), 0.05);
}

TEST(StreakAtlas, CellLookup) {
  const StreakAtlasLayout layout;  // 16 columns
  const auto resolved = StreakFootprint::resolved;
  const auto sub_pixel = StreakFootprint::sub_pixel;
  // Columns: motion 0, 0.5, 1, 2, … 32 (nearest in log2), resolved then sub-pixel.
  auto column = [&](double motion, StreakFootprint footprint) {
    return streak_atlas_cell(layout, motion, footprint, 0.01) % layout.columns();
  };
  EXPECT_EQ(column(0.0, resolved), 0);
  EXPECT_EQ(column(0.3, resolved), 0);
  EXPECT_EQ(column(0.5, resolved), 1);
  EXPECT_EQ(column(1.3, resolved), 2);   // log2 1.3 = 0.38 → 1
  EXPECT_EQ(column(80.0, resolved), 7);  // 32 and beyond
  EXPECT_EQ(column(80.0, sub_pixel), 15);
  // Rows: the nearest 2^(−r/8) to the opacity times the column's gain; above 1 counts as 1.
  auto row = [&](double motion, StreakFootprint footprint, double opacity) {
    return streak_atlas_cell(layout, motion, footprint, opacity) / layout.columns();
  };
  const double gain = streak_atlas_column_gain(layout, 15);
  EXPECT_EQ(row(80.0, sub_pixel, 0.5), static_cast<int>(std::lround(-8.0 * std::log2(0.5 * gain))));
  EXPECT_EQ(row(80.0, sub_pixel, 2.0), row(80.0, sub_pixel, 1.0));
  // Too faint for the last row, by more than half a step: −1 (frame_values never asks).
  const double floor = streak_atlas_faintest_coverage(layout);
  EXPECT_GE(streak_atlas_cell(layout, 80.0, sub_pixel, floor), 0);
  EXPECT_EQ(streak_atlas_cell(layout, 1.0, resolved, 0.0), -1);
  EXPECT_EQ(streak_atlas_cell(layout, 1.0, resolved, 1e-310), -1);  // subnormal
  EXPECT_EQ(streak_atlas_cell(layout, 1.0, resolved, layout.faintest_opacity() / 4.0), -1);
}

TEST(StreakAtlas, RowIsTheNearestEighthOfAHalvingWithinFourPercent) {
  // Checked against libm for opacities spread evenly in log2; the chosen row is never more than
  // 2^(1/16) = 4.4 % away from the opacity times the column's gain.
  const StreakAtlasLayout layout;
  const double gain = streak_atlas_column_gain(layout, layout.columns() - 1);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> level(0.0, 12.0);
  for (int i = 0; i < 100000; ++i) {
    const double opacity = std::exp2(-level(rng));
    // (32 sizes: the last column's own motion, drawn as it is.)
    const int cell = streak_atlas_cell(layout, 32.0, StreakFootprint::sub_pixel, opacity);
    const auto row = static_cast<int>(std::lround(-8.0 * std::log2(opacity * gain)));
    ASSERT_EQ(cell / layout.columns(), row) << opacity;
    ASSERT_NEAR(layout.row_opacity(row) / (opacity * gain), 1.0, 0.0443) << opacity;
  }
}

TEST(StreakAtlas, AStreakBetweenTwoColumnsStillCarriesTheDropsArea) {
  // A drop moving m sizes draws a quad (1 + m) sizes long at middle opacity min(1, 1/m) with
  // the nearest column's profile, made for its own motion: the cell's row makes up the
  // difference, so the quad carries the disc's π/4 (in sizes²) to the rows' 4.4 %. Out-of-focus
  // rain (frame_values.h) lands between the short columns, where the difference reached 7 %.
  const StreakAtlasLayout layout;
  const auto px = streak_atlas_pixels(layout);
  for (const double m : {0.7, 1.5, 3.0, 5.0, 6.0, 11.0, 24.0, 50.0, 95.0}) {
    for (const auto footprint : {StreakFootprint::resolved, StreakFootprint::sub_pixel}) {
      const double middle = 0.1 * std::min(1.0, 1.0 / m);  // a tenth: far from the clamp at 1
      const int cell = streak_atlas_cell(layout, m, footprint, middle);
      ASSERT_GE(cell, 0);
      const double carried =
          atlas_cell_mean(px, layout, cell / layout.columns(), cell % layout.columns()) *
          (1.0 + m) / 0.1;
      EXPECT_NEAR(carried / (std::numbers::pi / 4), 1.0, 0.045) << "motion " << m;
    }
  }
}

TEST(StreakAtlas, PngHoldsTheSixteenBitPixels) {
  StreakAtlasLayout layout;
  layout.motions = 2;
  layout.opacity_levels = 3;
  const auto path = raintrace::test_support::process_scratch_path("raintrace_atlas_test.png");
  write_streak_atlas(path, layout);
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path.string(), &config);
  ASSERT_TRUE(in);
  const OIIO::ImageSpec& spec = in->spec();
  EXPECT_EQ(spec.width, layout.width());
  EXPECT_EQ(spec.height, layout.height());
  EXPECT_EQ(spec.nchannels, 2);
  EXPECT_EQ(spec.format, OIIO::TypeDesc::UINT16);
  std::vector<std::uint16_t> read(static_cast<std::size_t>(spec.width) * spec.height * 2);
  ASSERT_TRUE(in->read_image(0, 0, 0, 2, OIIO::TypeDesc::UINT16, read.data()));
  in->close();
  EXPECT_EQ(read, streak_atlas_pixels(layout));
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace raintrace::povgen
