// night_street's roofs with the real POV-Ray (label `povray`; skipped without it). A terrace's
// skyline is pitched slate roofs and chimney stacks with pots, not the flat tops of its walls: a
// blind viewer of the storm, whose bolt lights the sky behind the rooflines, saw "clean stepped
// blocks with no gutters, chimneys, aerials or parapets". Both tests look at silhouettes against a
// white sky with an orthographic camera, 5 cm a pixel, and read the skyline off each column.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "povgen/povray_test_support.h"

namespace raintrace::povgen {
namespace {

namespace fs = std::filesystem;

constexpr double kMetresPerPixel = 0.05;

// The skyline of a silhouette picture `width` × `height` whose top row is at `top_m`: for each
// column, the height of the highest pixel that is not sky (red under half the sky's 1), or
// -1 where the column is all sky.
std::vector<double> skyline(const std::vector<float>& rgb, int width, int height, double top_m) {
  std::vector<double> heights(static_cast<std::size_t>(width), -1.0);
  if (rgb.size() != 3u * width * height) return heights;
  for (int column = 0; column < width; ++column) {
    for (int row = 0; row < height; ++row) {
      if (rgb[3u * (static_cast<std::size_t>(row) * width + column)] < 0.5f) {
        heights[column] = top_m - (row + 0.5) * kMetresPerPixel;
        break;
      }
    }
  }
  return heights;
}

// night_street (preview) seen by `camera`, the sky white: the view is silhouettes, and
// `extra` (SDL after the street) may add objects of its own.
std::string silhouette_scene(const std::string& camera, const std::string& extra) {
  return "#version 3.7;\n"
         "global_settings { assumed_gamma 1 }\n"
         "#declare RT_Preview = 1;\n"
         "#declare RT_CameraPosition = <0, 18, 17>;\n"
         "#include \"night_street.inc\"\n"
         "sky_sphere { pigment { rgb 1 } }\n" +
         extra + camera;
}

// The left-hand terrace, z = −30 to 64 m, seen side-on from the middle of the street, heights 8
// to 28 m. A chimney stack stands on each building's party wall with its pots: in the skyline, a
// spike under 1.5 m wide standing at least 0.5 m above the roof 1.5 m to either side of it. Steps
// from one building's height to the next are never spikes, and a wall top has none.
TEST(PovRayStreetRoofs, TheTerracesSkylineHasChimneyStacks) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_street_roofs");
  constexpr int kWidth = 1880;  // 94 m
  constexpr int kHeight = 400;  // 20 m
  const std::string camera =
      "camera { orthographic location <0, 18, 17> look_at <-1, 18, 17> right z * 94 up y * 20 }\n";
  const std::vector<float> rgb = testing::trace_linear(
      dir, "side", silhouette_scene(camera, ""),
      "+W" + std::to_string(kWidth) + " +H" + std::to_string(kHeight) + " -A");
  const std::vector<double> heights = skyline(rgb, kWidth, kHeight, 28.0);

  const int apart = static_cast<int>(std::lround(1.5 / kMetresPerPixel));
  int spikes = 0;
  int run = 0;  // columns in the current spike
  int widest = 0;
  for (int column = apart; column < kWidth - apart; ++column) {
    const double around = std::max(heights[column - apart], heights[column + apart]);
    const bool spike = heights[column] >= 0.0 && heights[column] - around >= 0.5;
    if (spike) {
      ++run;
    } else if (run > 0) {
      ++spikes;
      widest = std::max(widest, run);
      run = 0;
    }
  }
  std::printf("chimney stacks in the skyline: %d, the widest %.2f m\n", spikes,
              widest * kMetresPerPixel);
  // About ten buildings; a stack whose neighbour's roof rises past it 1.5 m on is not a spike.
  EXPECT_GE(spikes, 5) << "a terrace's skyline without chimney stacks";
  EXPECT_LE(widest * kMetresPerPixel, 1.5) << "a spike wider than a chimney stack";
  fs::remove_all(dir);
}

// The roof macro on its own: twelve roofs of buildings 10 m wide (along z) and 12 m deep (along
// x), set 30 m apart along x and seen end-on along +z, each on a wall 12 m high. Each pitched
// roof's gable rises from the parapet at 30–40° (slate needs 25° or more to shed rain; terraces
// like these were built at 30–45°), and four in five are pitched.
TEST(PovRayStreetRoofs, PitchedRoofsRiseAt30To40Degrees) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_street_gables");
  constexpr int kBuildings = 12;
  constexpr double kSpacing = 30.0;
  constexpr double kHeight = 12.0;  // the parapets' top
  constexpr int kWidth = static_cast<int>(kBuildings * kSpacing / kMetresPerPixel);
  constexpr int kRows = 200;  // 10 m, from 8 m up
  std::string roofs;
  for (int i = 0; i < kBuildings; ++i) {
    roofs += "union { RT_Roof(10, " + std::to_string(kHeight) +
             ", texture { pigment { rgb 0 } }) translate <" + std::to_string(1000 + i * kSpacing) +
             ", 0, 500> }\n";
  }
  const std::string camera =
      "camera { orthographic location <" + std::to_string(1000 + kBuildings * kSpacing / 2) +
      ", 13, 450> look_at <" + std::to_string(1000 + kBuildings * kSpacing / 2) +
      ", 13, 451> right x * " + std::to_string(kBuildings * kSpacing) + " up y * 10 }\n";
  // The roofs' union needs a wall below them against the sky: the gables start at the parapet.
  std::string walls;
  for (int i = 0; i < kBuildings; ++i) {
    walls += "box { <" + std::to_string(1000 + i * kSpacing) + ", 0, 500>, <" +
             std::to_string(1012 + i * kSpacing) + ", " + std::to_string(kHeight) +
             ", 510> pigment { rgb 0 } }\n";
  }
  const std::vector<float> rgb =
      testing::trace_linear(dir, "ends", silhouette_scene(camera, roofs + walls),
                            "+W" + std::to_string(kWidth) + " +H" + std::to_string(kRows) + " -A");
  const std::vector<double> heights = skyline(rgb, kWidth, kRows, 18.0);
  ASSERT_EQ(heights.size(), static_cast<std::size_t>(kWidth));

  // Each roof's front slope between 1 m and 3 m back from the facade (its chimney stack stands
  // 3.7 m back or more, the eaves 0.3 m back, behind the parapet).
  auto at = [&](double x) {
    return heights[static_cast<std::size_t>(std::lround((x - 1000.0) / kMetresPerPixel))];
  };
  int pitched = 0;
  for (int i = 0; i < kBuildings; ++i) {
    const double x0 = 1000.0 + i * kSpacing;
    const double rise = at(x0 + 3.0) - at(x0 + 1.0);
    if (rise < 0.2) continue;  // a flat roof: the parapet's top, level
    ++pitched;
    const double degrees = std::atan2(rise, 2.0) * 180.0 / std::numbers::pi;
    std::printf("roof %d: %.1f°\n", i, degrees);
    EXPECT_GE(degrees, 29.0) << "roof " << i;
    EXPECT_LE(degrees, 41.0) << "roof " << i;
  }
  EXPECT_GE(pitched, kBuildings / 2) << "most roofs are pitched";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace raintrace::povgen
