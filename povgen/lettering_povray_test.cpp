// night_street's lit fascia letters (RT_Lettering), with the real POV-Ray (ctest label
// `povray`; skipped without povray). A lit letter glows through its face; its sides (the
// returns) are painted metal, as a channel letter's are.
#include <gtest/gtest.h>

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

constexpr int kLetteringPixels = 400;

// An orthographic camera 4 m across looking at the middle of a lit word, `degrees` off the
// normal of the facade it stands on, toward the street's length, as a camera down the street
// sees a fascia, against the environment's sky (taken off by a render without the word).
std::string lettering_scene(double degrees, bool word = true) {
  const double a = degrees * std::numbers::pi / 180.0;
  return "#version 3.7;\n"
         "global_settings { assumed_gamma 1 }\n"
         "#declare RT_CameraPosition = <0, 1.45, 0>;\n"
         "#declare RT_LightsOnly = 1;\n"  // the macros without the street
         "#include \"night_street.inc\"\n"
         "#declare RT_Side = 1;\n"
         "#declare Centre = <-0.13, 3.375, 14>;\n"
         "camera { orthographic location Centre + 20 * <" +
         std::to_string(-std::cos(a)) + ", 0, " + std::to_string(-std::sin(a)) +
         "> look_at Centre right 4 * x up 4 * y }\n" +
         // RT_Lettering(Name, Z0, Z1, Y0, Y1, Ink, Lit), in a building's frame whose facade is
         // x = 0; the letters' face stands at x = −0.121 − their depth.
         std::string(word ? "RT_Lettering(\"KEBAB HOUSE\", 12, 16, 3.05, 3.7, <1, 1, 1>, 1)\n"
                          : "");
}

// Through an orthographic camera a picture's summed light is the radiance times the area the
// camera sees. A flat glowing face seen 80° off its normal shows cos 80° = 0.174 of the area it
// shows head-on, so the word's light seen that way must be 0.174 of its light seen head-on,
// within 10 %. Measured: 0.181 (the glowing sliver's own sides, 0.5 mm deep, add a little).
// While the whole letter glowed, its sides, 1 cm deep and facing along the street, added 57 % to
// the face's light seen from there: 0.273 (and the road's mirror saw the signs that bright).
TEST(PovRayLettering, ALitLetterGlowsThroughItsFaceNotItsSides) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_lettering");
  const std::string options = testing::square_size(kLetteringPixels) + " +A0.01 +AM2 +R3";
  const auto head_on = testing::trace_linear(dir, "head_on", lettering_scene(0), options);
  const auto oblique = testing::trace_linear(dir, "oblique", lettering_scene(80), options);
  const auto sky = testing::trace_linear(dir, "sky", lettering_scene(0, false), options);
  const auto sky_oblique =
      testing::trace_linear(dir, "sky_oblique", lettering_scene(80, false), options);
  ASSERT_EQ(head_on.size(), 3u * kLetteringPixels * kLetteringPixels);
  ASSERT_EQ(oblique.size(), head_on.size());
  ASSERT_EQ(sky.size(), head_on.size());
  ASSERT_EQ(sky_oblique.size(), head_on.size());
  double head_on_light = 0.0, oblique_light = 0.0;
  for (std::size_t i = 0; i < head_on.size(); i += 3) {
    head_on_light += head_on[i] - sky[i];
    oblique_light += oblique[i] - sky_oblique[i];
  }
  ASSERT_GT(head_on_light, 0.0) << "the camera sees no letters";
  const double expected = std::cos(80.0 * std::numbers::pi / 180.0);
  std::printf("a lit word's light 80 degrees off its normal over head-on: %.4f (cos 80 = %.4f)\n",
              oblique_light / head_on_light, expected);
  EXPECT_NEAR(oblique_light / head_on_light, expected, 0.1 * expected);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace raintrace::povgen
