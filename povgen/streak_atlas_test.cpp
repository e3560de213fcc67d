// Streak atlas: size, opacity halving per row, shapes, the cell lookup and the PNG file.
#include "povgen/streak_atlas.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

namespace raintrace::povgen {
namespace {

int alpha_at(const std::vector<std::uint8_t>& px, const StreakAtlasLayout& l, int x, int y) {
  return px[(static_cast<std::size_t>(y) * l.width() + x) * 4 + 3];
}

/// Largest alpha within one cell (row counted from the bottom, as POV-Ray's v).
int peak_alpha(const std::vector<std::uint8_t>& px, const StreakAtlasLayout& l, int row,
               int column) {
  int peak = 0;
  for (int y = 0; y < l.cell_height; ++y) {
    const int py = l.height() - 1 - (row * l.cell_height + y);
    for (int x = 0; x < l.cell_width; ++x) {
      peak = std::max(peak, alpha_at(px, l, column * l.cell_width + x, py));
    }
  }
  return peak;
}

TEST(StreakAtlas, EachRowHalvesTheOpacity) {
  const StreakAtlasLayout layout;
  const auto px = streak_atlas_pixels(layout);
  ASSERT_EQ(px.size(), static_cast<std::size_t>(layout.width()) * layout.height() * 4);
  // Peak of row r: 255·2^-r times the profile's maximum. Across the body the profile is 1; the
  // fade along is 0.85 + 0.15·y, largest where the leading cap (18 % of the cell) begins:
  // y = 0.82 → 0.973.
  for (int row = 0; row < layout.opacity_levels; ++row) {
    const double expected = 255.0 * 0.973 * std::ldexp(1.0, -row);
    EXPECT_NEAR(peak_alpha(px, layout, row, 0), expected, 1.0 + 0.01 * expected) << row;
  }
}

TEST(StreakAtlas, StreaksFadeTowardTheirRimAndEnds) {
  const StreakAtlasLayout layout;
  const auto px = streak_atlas_pixels(layout);
  // Row 0 is the bottom band; its middle image row is height − cell_height/2.
  const int middle_y = layout.height() - layout.cell_height / 2;
  const int centre = alpha_at(px, layout, layout.cell_width / 2, middle_y);
  const int rim = alpha_at(px, layout, 0, middle_y);
  EXPECT_GT(centre, 200);
  EXPECT_LT(rim, centre / 2);
  // The trailing end (top of the cell) and leading end (bottom) are clear at the very edge.
  EXPECT_LT(alpha_at(px, layout, layout.cell_width / 2, layout.height() - layout.cell_height), 40);
  EXPECT_LT(alpha_at(px, layout, layout.cell_width / 2, layout.height() - 1), 40);
}

TEST(StreakAtlas, FlatterShapesHaveShorterLeadingEnds) {
  // The leading cap shrinks with flatness: a few texels above the cell bottom a flattened
  // drop's streak is already full while the round one is still tapering.
  const StreakAtlasLayout layout;
  const auto px = streak_atlas_pixels(layout);
  const int y = layout.height() - 4;
  const int round = alpha_at(px, layout, layout.cell_width / 2, y);
  const int flat =
      alpha_at(px, layout, (layout.shapes - 1) * layout.cell_width + layout.cell_width / 2, y);
  EXPECT_GT(flat, round);
}

TEST(StreakAtlas, CellLookup) {
  const StreakAtlasLayout layout;  // 8 shapes × 8 levels
  EXPECT_EQ(streak_atlas_cell(layout, 1.0, 1.0), 0);
  EXPECT_EQ(streak_atlas_cell(layout, 0.5, 1.0), 7);
  EXPECT_EQ(streak_atlas_cell(layout, 1.0, 0.25), 2 * 8);        // −log2 0.25 = 2
  EXPECT_EQ(streak_atlas_cell(layout, 0.75, 0.125), 3 * 8 + 4);  // flatness 0.5 → column 3.5→4
  EXPECT_EQ(streak_atlas_cell(layout, 1.0, 1.0 / 128), 7 * 8);
  EXPECT_EQ(streak_atlas_cell(layout, 1.0, 1.0 / 512), -1);  // too faint: not written
  EXPECT_EQ(streak_atlas_cell(layout, 1.0, 0.0), -1);
}

TEST(StreakAtlas, RowIsTheNearestHalvingOfTheOpacity) {
  // The row is round(−log2 opacity), the column round(flatness · 7): checked against libm's
  // log2 and lround for opacities spread evenly in log2 (row boundaries at 2^−(r+½)).
  const StreakAtlasLayout layout;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> level(0.0, 9.0);
  std::uniform_real_distribution<double> ratio(0.5, 1.0);
  for (int i = 0; i < 100000; ++i) {
    const double opacity = std::exp2(-level(rng));
    const double axis_ratio = ratio(rng);
    const auto row = static_cast<int>(std::lround(-std::log2(opacity)));
    const auto column = static_cast<int>(std::lround((1.0 - axis_ratio) / 0.5 * 7));
    const int expected = row >= 8 ? -1 : row * 8 + column;
    ASSERT_EQ(streak_atlas_cell(layout, axis_ratio, opacity), expected) << opacity;
  }
  EXPECT_EQ(streak_atlas_cell(layout, 1.0, 0.7072), 0);   // −log2 = 0.49987
  EXPECT_EQ(streak_atlas_cell(layout, 1.0, 0.7070), 8);   // −log2 = 0.50029
  EXPECT_EQ(streak_atlas_cell(layout, 1.0, 2.0), 0);      // opacity above 1 counts as 1
  EXPECT_EQ(streak_atlas_cell(layout, 1.0, 1e-310), -1);  // subnormal
}

TEST(StreakAtlas, PngHoldsThePixels) {
  const StreakAtlasLayout layout{4, 2, 8, 16};
  const auto path = std::filesystem::temp_directory_path() / "raintrace_atlas_test.png";
  write_streak_atlas(path, layout);
  // PNG alpha is unassociated: ask OpenImageIO not to premultiply on reading.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path.string(), &config);
  ASSERT_TRUE(in);
  const OIIO::ImageSpec& spec = in->spec();
  EXPECT_EQ(spec.width, layout.width());
  EXPECT_EQ(spec.height, layout.height());
  EXPECT_EQ(spec.nchannels, 4);
  std::vector<std::uint8_t> read(static_cast<std::size_t>(spec.width) * spec.height * 4);
  ASSERT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, read.data()));
  in->close();
  EXPECT_EQ(read, streak_atlas_pixels(layout));
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace raintrace::povgen
