// The wet road's glossy streak under a streetlight (night_street's RT_LampStreak), with the real
// POV-Ray (ctest label `povray`; skipped without povray). A streetlight's lens is flat and faces
// down, so a point of the road sees its area foreshortened by cos θ, θ the angle from straight
// down at which that point sees the lens; the streak must carry the lens's light weighted so.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "povgen/povray_test_support.h"

namespace raintrace::povgen {
namespace {

namespace fs = std::filesystem;

constexpr int kSize = 200;

// A camera 1.45 m above a perfect mirror (the road, reflection 1, no Fresnel), looking at the
// point where it sees the mirror image of a lens 5.88 m up and 22 m ahead: 4.352 m ahead
// (1.45 · 22 / 7.33), the middle of the picture. `streak` is the RT_LampStreak call, or empty.
std::string mirror_scene(const std::string& streak) {
  return "#version 3.7;\n"
         "global_settings { assumed_gamma 1 }\n"
         "#declare RT_CameraPosition = <0, 1.45, 0>;\n"
         "#declare RT_LightsOnly = 1;\n"  // the macros without the street
         "#include \"night_street.inc\"\n"
         "#declare RT_Mirror = 0.5;\n"
         "camera { perspective location RT_CameraPosition look_at <0, 0, 4.352> angle 30 }\n"
         "plane { y, 0 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 1 } }\n" +
         streak + "\n";
}

// Mean red of the 3×3 pixels around (x, y) of a linear RGB image kSize wide.
double red_around(const std::vector<float>& px, int x, int y) {
  double sum = 0.0;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) sum += px[3 * ((y + dy) * kSize + x + dx)];
  }
  return sum / 9.0;
}

// Where the camera sees the mirror image of the lens, the road reflects the lens from
// d_p = 4.352 m: the lens lies 17.65 m away horizontally and 5.88 m up, θ = 71.6° from straight
// down, cos θ = 0.315. The streak of a lens facing down (FacesDown 1) must be that share of the
// streak of one facing the camera (FacesDown 0), the background (no streak) taken off; and it
// must weaken toward the camera (lower in the picture), where the road sees the lens more
// obliquely, while the camera-facing streak's Gaussian falls off symmetrically.
TEST(PovRayLampStreak, AStreetlightsStreakIsItsLensForeshortenedAsTheRoadSeesIt) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_lamp_streak");
  const std::string lamp = "RT_LampStreak(<0, 5.88, 22>, 40, <1, 1, 1>, ";
  const std::string options = testing::square_size(kSize) + " -A";
  const auto down = testing::trace_linear(dir, "down", mirror_scene(lamp + "1)"), options);
  const auto facing = testing::trace_linear(dir, "facing", mirror_scene(lamp + "0)"), options);
  const auto none = testing::trace_linear(dir, "none", mirror_scene(""), options);
  ASSERT_EQ(down.size(), 3u * kSize * kSize);
  ASSERT_EQ(facing.size(), down.size());
  ASSERT_EQ(none.size(), down.size());

  // The streak's brightest row in the middle column: the Gaussian's peak, the lens's image.
  const int x = kSize / 2;
  int peak = 1;
  for (int y = 1; y < kSize - 1; ++y) {
    if (red_around(facing, x, y) > red_around(facing, x, peak)) peak = y;
  }
  const auto streak = [&](const std::vector<float>& px, int y) {
    return red_around(px, x, y) - red_around(none, x, y);
  };
  ASSERT_GT(streak(facing, peak), 1.0) << "the mirror shows no streak";
  ASSERT_NEAR(peak, kSize / 2, 5) << "the streak's peak is not at the lens's mirror image";
  const double at_peak = streak(down, peak) / streak(facing, peak);
  std::printf("streak of a lens facing down over one facing the camera: %.3f at row %d\n", at_peak,
              peak);
  EXPECT_NEAR(at_peak, 0.315, 0.02) << "not the lens foreshortened by cos θ";

  // 20 rows either side of the peak: the ratio falls toward the camera (below the peak).
  const double above = streak(down, peak - 20) / streak(facing, peak - 20);
  const double below = streak(down, peak + 20) / streak(facing, peak + 20);
  std::printf("20 rows above: %.3f, below: %.3f\n", above, below);
  EXPECT_GT(above, at_peak);
  EXPECT_LT(below, at_peak);
  fs::remove_all(dir);
}

// The lens the mirror tests light: facing down, 7 cm above the point its light is counted from,
// as the street's are; thin, so that all its light leaves through its face, and three times as
// wide and deep as theirs, so that its foreshortened image spans a few rows and its light is
// sampled well. As a shape (RT_MirroredLens) and as RT_MirroredFlatLens's centre and half sizes.
const std::string kTestLens =
    "box { <-0.84, -0.0001, -0.36>, <0.84, 0, 0.36> translate <0, 5.95, 22> }";
const std::string kTestFlatLens = "<0, 5.95, 22>, <0.84, 0.0001, 0.36>";

// Every mirror shows a lamp's light once: its lens at RT_Mirror of its light (a streetlight's
// RT_MirroredFlatLens, a blurred copy only reflections see) and its streak the rest. In a perfect
// mirror the two must carry the light of the lens alone, mirrored at its full light, within 3 %:
// each picture's light summed, the street's own lamps (a background render) taken off. They are
// rendered apart: together the lens hides the core of its streak behind it (3.9 % of the whole for
// this lens three times the street's; ~1.5 % for theirs). Measured: 0.9889 with the even
// copy, 1.0015 with it blurred twice its half sizes, 0.9966 four times (RT_LensBlur). While the
// streak's light was divided by RT_Mirror for the road's half-strength mirror, a puddle saw each
// lamp's light 1.8 times over by that formula (the lens at full light, the streak at 0.8 of what
// it stood for: it made up neither for the 4 % pedestal its Gaussian is cut at nor for standing
// 30 cm behind the lens).
TEST(PovRayLampStreak, AMirrorShowsALampsLightOnce) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_lamp_once");
  const std::string options = testing::square_size(kSize) + " +A0.01 +AM2 +R3";
  const auto copy = testing::trace_linear(
      dir, "copy", mirror_scene("RT_MirroredFlatLens(" + kTestFlatLens + ", <1, 1, 1>, 40)"),
      options);
  const auto streak = testing::trace_linear(
      dir, "streak", mirror_scene("RT_LampStreak(<0, 5.88, 22>, 40 * 1.68 * 0.72, <1, 1, 1>, 1)"),
      options);
  const auto alone = testing::trace_linear(
      dir, "lens",
      mirror_scene("object { " + kTestLens +
                   " texture { pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 40 } } "
                   "no_image }"),
      options);
  const auto none = testing::trace_linear(dir, "none", mirror_scene(""), options);
  ASSERT_EQ(copy.size(), 3u * kSize * kSize);
  ASSERT_EQ(streak.size(), copy.size());
  ASSERT_EQ(alone.size(), copy.size());
  ASSERT_EQ(none.size(), copy.size());
  double lamp_once = 0.0, lens_alone = 0.0;
  for (std::size_t i = 0; i < copy.size(); i += 3) {
    lamp_once += copy[i] + streak[i] - 2 * none[i];
    lens_alone += alone[i] - none[i];
  }
  ASSERT_GT(lens_alone, 0.0) << "the mirror shows no lens";
  std::printf("a mirrored lamp's light, lens and streak over the lens alone: %.4f\n",
              lamp_once / lens_alone);
  EXPECT_NEAR(lamp_once / lens_alone, 1.0, 0.03);
  fs::remove_all(dir);
}

// A streetlight's copy for mirrors is its lens blurred (RT_MirroredFlatLens): in a perfect
// mirror it must carry the light of the even copy RT_MirroredLens draws of the same lens, within
// 3 %, spread wider and no brighter: the pixels it lights past a hundredth of the even copy's
// brightest at least 8 times as many (the ellipse, RT_LensBlur = 4 times the lens's half sizes,
// has 4π = 12.6 times the lens's area, its light falling to 0 at the rim), its brightest at most
// 0.3 of the even copy's (its middle is 12/(16π) = 0.239 of the lens's radiance). Measured:
// 1.023 of the light, 10.9 times the pixels, 0.23 of the peak (at RT_LensBlur 2, until
// 2026-12-07: 1.025, 3.1 times, 0.90).
TEST(PovRayLampStreak, AStreetlightsMirroredCopyIsItsLensBlurredWithItsLightKept) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_lens_blur");
  const std::string options = testing::square_size(kSize) + " +A0.01 +AM2 +R3";
  const auto even = testing::trace_linear(
      dir, "even", mirror_scene("RT_MirroredLens(" + kTestLens + ", <1, 1, 1>, 40)"), options);
  const auto blurred = testing::trace_linear(
      dir, "blurred", mirror_scene("RT_MirroredFlatLens(" + kTestFlatLens + ", <1, 1, 1>, 40)"),
      options);
  const auto none = testing::trace_linear(dir, "none", mirror_scene(""), options);
  ASSERT_EQ(even.size(), 3u * kSize * kSize);
  ASSERT_EQ(blurred.size(), even.size());
  ASSERT_EQ(none.size(), even.size());
  const testing::LightSpread spread = testing::light_spread(even, blurred, none);
  ASSERT_GT(spread.sharp_light, 0.0) << "the mirror shows no lens";
  std::printf("the blurred copy's light %.4f of the even copy's, %d pixels against %d, peak %.3f\n",
              spread.light_ratio, spread.blurred_lit, spread.sharp_lit, spread.peak_ratio);
  EXPECT_NEAR(spread.light_ratio, 1.0, 0.03);
  EXPECT_GE(spread.blurred_lit, 8 * spread.sharp_lit) << "the copy is not spread";
  EXPECT_LE(spread.peak_ratio, 0.3) << "the copy's middle is not dimmed for its spread";
  fs::remove_all(dir);
}

// A lit shop's ceiling panel is a small source far brighter than what lies around it, as a lens
// is: mirrors see it at RT_Mirror of its light (RT_ShopPanel's copy, blurred RT_PanelBlur beyond
// the panel on every side) and its streak carries the rest (RT_PanelStreaks: RT_BarStreak for
// each piece of at most 2 m). In a perfect mirror the copy must be RT_Mirror of the panel's face
// mirrored at its full light, within 2 %, and the copy and the streaks together its full light,
// within 5 %. Measured: 0.5001 and 0.981 (one sheet for the whole 8 m panel gave 0.911: what the
// road sees of the bar falls as cos θ / d² along it). Against the whole panel, its 3 cm sides
// included, the even copy of 2026-12-03 carried 0.4997 and the blurred one, a flat rectangle,
// 0.472. The panel runs along the street 4 m to the side, 10–18 m ahead, as the
// near kebab house's do; the camera looks at its mirror image, wide enough to hold the streaks'
// tails.
TEST(PovRayLampStreak, AMirrorShowsAShopPanelsLightOnce) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_panel_once");
  const auto scene = [](const std::string& objects) {
    return "#version 3.7;\n"
           "global_settings { assumed_gamma 1 }\n"
           "#declare RT_CameraPosition = <0, 1.45, 0>;\n"
           "#declare RT_LightsOnly = 1;\n"
           "#include \"night_street.inc\"\n"
           "#declare RT_Mirror = 0.5;\n"
           "camera { perspective location RT_CameraPosition look_at <1.315, 0, 4.603> angle 90 }\n"
           "plane { y, 0 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 1 } }\n"
           // A black ceiling just above the camera that only its own rays meet: it hides the
           // panel as the camera sees it, mirrors see past it.
           "plane { y, 1.5 pigment { rgb 0 } finish { ambient 0 diffuse 0 } no_reflection }\n" +
           objects + "\n";
  };
  // RT_ShopPanel(X0, Z0, Z1, Colour): 0.6 m wide from X0, its lit face 2.96 m up.
  const std::string panel = "RT_ShopPanel(3.7, 10, 18, <1, 1, 1>)";
  const std::string options = testing::square_size(kSize) + " +A0.01 +AM2 +R3";
  // The copy alone (the panel as the camera sees it is behind the ceiling).
  const auto copy = testing::trace_linear(dir, "copy", scene(panel), options);
  // The streaks alone: the panel recorded, then drawn as RT_PanelStreaks draws the street's.
  const auto streaks = testing::trace_linear(dir, "streaks",
                                             scene("#declare RT_PanelCentre[0] = <4, 2.96, 14>;\n"
                                                   "#declare RT_PanelLength[0] = 8;\n"
                                                   "#declare RT_PanelColour[0] = <1, 1, 1>;\n"
                                                   "#declare RT_PanelN = 1;\n"
                                                   "RT_PanelStreaks()"),
                                             options);
  const auto alone = testing::trace_linear(
      dir, "alone",
      scene("box { <3.7, 2.96, 10>, <4.3, 2.9601, 18> texture { pigment { rgb 1 } finish { "
            "ambient 0 diffuse 0 emission RT_ShopPanelEmission } } no_image }"),
      options);
  const auto none = testing::trace_linear(dir, "none", scene(""), options);
  ASSERT_EQ(copy.size(), 3u * kSize * kSize);
  ASSERT_EQ(streaks.size(), copy.size());
  ASSERT_EQ(alone.size(), copy.size());
  ASSERT_EQ(none.size(), copy.size());
  double copy_light = 0.0, streak_light = 0.0, panel_alone = 0.0;
  for (std::size_t i = 0; i < copy.size(); i += 3) {
    copy_light += copy[i] - none[i];
    streak_light += streaks[i] - none[i];
    panel_alone += alone[i] - none[i];
  }
  ASSERT_GT(panel_alone, 0.0) << "the mirror shows no panel";
  std::printf("a mirrored panel's copy %.4f and streaks %.4f of the panel alone, together %.4f\n",
              copy_light / panel_alone, streak_light / panel_alone,
              (copy_light + streak_light) / panel_alone);
  EXPECT_NEAR(copy_light / panel_alone, 0.5, 0.02) << "the copy is not RT_Mirror of the panel";
  EXPECT_NEAR((copy_light + streak_light) / panel_alone, 1.0, 0.05);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace raintrace::povgen
