// night_street's centre-line dashes (RT_DashDistance), with the real POV-Ray (ctest label
// `povray`; skipped without povray). A dash's pigment is chosen by how far a point lies from the
// dash's middle, 0 on its centre line and 1 at its worn rim. POV-Ray wraps a pigment function's
// value into 0..1, so a value pushed below 0 by the rim's noise comes back near 1, the asphalt's
// end of the map: until 2026-12-05 every dash had a wandering dark line down its middle.
// The yellow lines of the waiting restrictions run along the kerbs, double or single, and the
// gullies' gratings beside them drain through slots.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "povgen/povray_test_support.h"

namespace raintrace::povgen {
namespace {

namespace fs = std::filesystem;

constexpr int kAcross = 16;  // pixels across the 4 cm strip around the centre line
constexpr int kAlong = 560;  // pixels along 2.8 m of the dash (z from 0.1 to 2.9)

TEST(PovRayRoadMarkings, ADashIsPaintAllAlongItsMiddle) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_road_markings");
  // The first dash beyond the origin lies at |x| <= 0.06, 0 <= z <= 3. Seen from straight above,
  // the middle 4 cm of it: the distance function itself as grey, emitted, on a sheet over the
  // street.
  const std::string scene =
      "#version 3.7;\n"
      "global_settings { assumed_gamma 1 }\n"
      "#include \"night_street.inc\"\n"
      "camera { orthographic location <0, 0.5, 1.5> look_at <0, 0, 1.5> sky z\n"
      "         right -x * 0.04 up z * 2.8 }\n"
      "plane { y, 0.01 pigment { function { RT_DashDistance(x, 0, z) } }\n"
      "        finish { ambient 0 diffuse 0 emission 1 } no_shadow }\n";
  const std::vector<float> picture = testing::trace_linear(
      dir, "dash", scene, "+W" + std::to_string(kAcross) + " +H" + std::to_string(kAlong) + " -A");
  fs::remove_all(dir);
  ASSERT_EQ(picture.size(), 3u * kAcross * kAlong);
  // The rim's noise moves the edge by at most 0.35 · 0.5 half-widths, 1 cm: within 2 cm of the
  // centre line (the middle 8 columns), every point is well inside the dash (the pigment map
  // turns to asphalt from 0.82). 0.5 leaves room for the noise.
  float highest = 0.0f;
  for (int row = 0; row < kAlong; ++row) {
    for (int column = kAcross / 4; column < 3 * kAcross / 4; ++column) {
      highest = std::max(highest, picture[3u * (row * kAcross + column)]);
    }
  }
  EXPECT_LT(highest, 0.5f) << "asphalt shows down the middle of a dash";
}

/// The night street's road from straight above, lit from overhead (and by the street's own
/// lamps): `across_m` along x by `along_m` along z around (x, z), the picture's columns running
/// along +x and its rows along z, traced in linear light with `options`.
std::vector<float> road_from_above(const fs::path& dir, const std::string& name, double x, double z,
                                   double across_m, double along_m, const std::string& options) {
  // The camera given as vectors, not look_at, so the picture's columns run along +x as written.
  const std::string scene = fmt::format(
      "#version 3.7;\n"
      "global_settings {{ assumed_gamma 1 }}\n"
      "#include \"night_street.inc\"\n"
      "camera {{ orthographic location <{0}, 0.5, {1}> direction -y right x * {2} up z * {3} }}\n"
      "light_source {{ <{0}, 100, {1}> rgb 10 parallel point_at <{0}, 0, {1}> shadowless }}\n",
      x, z, across_m, along_m);
  return testing::trace_linear(dir, name, scene, options);
}

constexpr int kKerbColumns = 240;  // pixels across the 0.6 m of road beside the left kerb
constexpr int kKerbRows = 40;      // pixels along 1 m of it

/// How yellow the road is across the 0.6 m beside the left kerb (x from −4 to −3.4), from
/// straight above, lit from overhead, over 1 m of the street from z = Z: each column's mean red
/// less its mean blue, the kerb's face first.
std::vector<double> yellow_across_left_kerb(const fs::path& dir, const std::string& name,
                                            double z) {
  const std::string size = "+W" + std::to_string(kKerbColumns) + " +H" + std::to_string(kKerbRows);
  const std::vector<float> picture =
      road_from_above(dir, name, -3.7, z + 0.5, 0.6, 1.0, size + " +A0.05 +AM2 +R2");
  std::vector<double> yellow(kKerbColumns, 0.0);
  if (picture.size() != 3u * kKerbColumns * kKerbRows) return yellow;
  for (int column = 0; column < kKerbColumns; ++column) {
    for (int row = 0; row < kKerbRows; ++row) {
      const std::size_t i = 3u * (row * kKerbColumns + column);
      yellow[column] += (picture[i] - picture[i + 2]) / kKerbRows;
    }
  }
  return yellow;
}

/// The mean of `values` over the columns that lie from `from_m` to `to_m` out from the kerb.
double mean_between(const std::vector<double>& values, double from_m, double to_m) {
  const auto first = static_cast<int>(from_m / 0.6 * kKerbColumns);
  const auto last = static_cast<int>(to_m / 0.6 * kKerbColumns);
  double sum = 0.0;
  for (int column = first; column < last; ++column) sum += values[column];
  return sum / (last - first);
}

TEST(PovRayRoadMarkings, WaitingLinesAlongTheLeftKerbRunDoubleThenSingle) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_waiting_lines");
  // Double lines from the camera's end to z = 24, a single one from there to z = 54: lines
  // 50 mm wide from 250 mm out, a line's width apart. Their middles, with a centimetre kept
  // clear of each worn rim: 0.26–0.29 m and 0.36–0.39 m out; between them 0.31–0.34 m; the
  // asphalt beyond, 0.45–0.6 m, and next to the kerb, 0.05–0.2 m. Each metre is clear of the
  // left-hand lamps (z = 16, 40): looking straight down, the wet road mirrors what hangs right
  // above it, and a lamp's copy for mirrors (RT_LensBlur) reaches 1.12 m either side of its lens
  // at x = −2.6, to x = −3.72, into the strip measured here.
  const std::vector<double> double_lines = yellow_across_left_kerb(dir, "double", 10.0);
  const std::vector<double> single_line = yellow_across_left_kerb(dir, "single", 33.0);
  fs::remove_all(dir);
  const double asphalt = std::max({std::fabs(mean_between(double_lines, 0.45, 0.6)),
                                   std::fabs(mean_between(double_lines, 0.05, 0.2)),
                                   std::fabs(mean_between(single_line, 0.45, 0.6)), 1e-4});
  // Yellow paint: red well above blue, as the asphalt's grey is not.
  EXPECT_GT(mean_between(double_lines, 0.26, 0.29), 10 * asphalt) << "the kerb's line";
  EXPECT_GT(mean_between(double_lines, 0.36, 0.39), 10 * asphalt) << "the double's second line";
  EXPECT_LT(mean_between(double_lines, 0.31, 0.34), 0.2 * mean_between(double_lines, 0.26, 0.29))
      << "the two lines of the double run together";
  EXPECT_GT(mean_between(single_line, 0.26, 0.29), 10 * asphalt) << "the single line";
  EXPECT_LT(mean_between(single_line, 0.36, 0.39), 0.2 * mean_between(single_line, 0.26, 0.29))
      << "a second line where the line is single";
}

TEST(PovRayRoadMarkings, AGullyGratingShowsItsSevenSlotsBetweenIronBars) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_gully");
  // The left kerb's first grating, 0.45 m along the kerb at z = 3.5, from straight above and lit
  // from overhead: a line of 90 pixels along its middle, 0.2 m out from the kerb, from z = 3.275
  // to 3.725, 5 mm a pixel.
  constexpr int kAlongGrating = 90;
  const std::vector<float> picture = road_from_above(
      dir, "gully", -3.8, 3.5, 0.005, 0.45, "+W1 +H" + std::to_string(kAlongGrating) + " -A");
  fs::remove_all(dir);
  ASSERT_EQ(picture.size(), 3u * kAlongGrating);
  // Bars and frame are wet iron lit from above; the slots open onto the dark pot. Counted from
  // the far end to the near: runs of pixels darker than a quarter of the brightest.
  float brightest = 0.0f;
  for (int row = 0; row < kAlongGrating; ++row) brightest = std::max(brightest, picture[3u * row]);
  ASSERT_GT(brightest, 0.0f);
  int slots = 0;
  bool in_slot = false;
  for (int row = 0; row < kAlongGrating; ++row) {
    const bool dark = picture[3u * row] < 0.25f * brightest;
    if (dark && !in_slot) ++slots;
    in_slot = dark;
  }
  EXPECT_EQ(slots, 7);
}

}  // namespace
}  // namespace raintrace::povgen
