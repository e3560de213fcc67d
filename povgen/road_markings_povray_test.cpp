// night_street's centre-line dashes (RT_DashDistance), with the real POV-Ray (ctest label
// `povray`; skipped without povray). A dash's pigment is chosen by how far a point lies from the
// dash's middle, 0 on its centre line and 1 at its worn rim. POV-Ray wraps a pigment function's
// value into 0..1, so a value pushed below 0 by the rim's noise comes back near 1, the asphalt's
// end of the map: until 2026-12-05 every dash had a wandering dark line down its middle.
#include <gtest/gtest.h>

#include <algorithm>
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

}  // namespace
}  // namespace raintrace::povgen
