// night_street's lit fascia letters (RT_Lettering), with the real POV-Ray (ctest label
// `povray`; skipped without povray). A lit letter glows through its face; its sides (the
// returns) are painted metal, as a channel letter's are.
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

// A signwriter spaces fascia capitals apart, and the emboldening (RT_Embolden to each side)
// would close the font's own gaps by a third: seen along the street, letters that touch run
// together into blobs ("4EBABS", "mushy, half-formed letters": blind viewers). Head-on, every
// letter of KEBAB HOUSE must stand apart from the next, in columns of sky at least
// kLetterGapCaps of the capital height wide. Measured (capitals 34 pixels tall): 0.118 with
// RT_LetterSpacing 0.1, 0.059 without it.
constexpr double kLetterGapCaps = 0.09;

TEST(PovRayLettering, AFasciaWordsLettersStandApart) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_letter_gaps");
  const std::string options = testing::square_size(kLetteringPixels) + " -A";
  const auto word = testing::trace_linear(dir, "word", lettering_scene(0), options);
  const auto sky = testing::trace_linear(dir, "sky", lettering_scene(0, false), options);
  ASSERT_EQ(word.size(), 3u * kLetteringPixels * kLetteringPixels);
  ASSERT_EQ(sky.size(), word.size());
  // Which columns and rows hold a glowing letter (well above the sky's light).
  std::vector<bool> column_lit(kLetteringPixels, false);
  int top = kLetteringPixels, bottom = -1;
  for (int y = 0; y < kLetteringPixels; ++y) {
    for (int x = 0; x < kLetteringPixels; ++x) {
      const std::size_t i = 3u * (std::size_t(y) * kLetteringPixels + std::size_t(x));
      if (word[i] - sky[i] > 1.0) {
        column_lit[std::size_t(x)] = true;
        top = std::min(top, y);
        bottom = std::max(bottom, y);
      }
    }
  }
  ASSERT_GE(bottom, top) << "the camera sees no letters";
  const double cap_px = bottom - top + 1;  // capitals only: KEBAB HOUSE has no descender
  // Runs of lit columns: one a letter; the gaps between them, in capital heights.
  std::vector<int> gaps;
  int run_end = -1;
  for (int x = 0; x < kLetteringPixels; ++x) {
    if (!column_lit[std::size_t(x)]) continue;
    if (run_end >= 0 && x > run_end + 1) gaps.push_back(x - run_end - 1);
    run_end = x;
  }
  // Ten letters, nine gaps, one of them the space between the words.
  EXPECT_EQ(gaps.size(), 9u) << "letters touching or split";
  ASSERT_FALSE(gaps.empty());
  const double narrowest = *std::min_element(gaps.begin(), gaps.end()) / cap_px;
  std::printf("KEBAB HOUSE head-on: %zu gaps, the narrowest %.3f of the capital height\n",
              gaps.size(), narrowest);
  EXPECT_GE(narrowest, kLetterGapCaps);
  fs::remove_all(dir);
}

// A camera looking at a perfect mirror (the road, reflection 1) where it shows PHARMACY lit on
// its fascia, 39° off the face's normal. `blur` declares RT_LetterBlur (empty: the template's).
std::string mirrored_word_scene(const std::string& blur, bool word = true) {
  return "#version 3.7;\n"
         "global_settings { assumed_gamma 1 }\n"
         "#declare RT_CameraPosition = <-6, 1.45, 14>;\n"
         "#declare RT_LightsOnly = 1;\n" +
         (blur.empty() ? "" : "#declare RT_LetterBlur = " + blur + ";\n") +
         "#include \"night_street.inc\"\n"
         "#declare RT_Side = 1;\n"
         "camera { perspective location RT_CameraPosition look_at <-0.13, -3.375, 14> angle 40 }\n"
         "plane { y, 0 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 1 } }\n" +
         std::string(word ? "RT_Lettering(\"PHARMACY\", 12, 16, 3.05, 3.7, <1, 1, 1>, 1)\n" : "");
}

// Mirrors see a lit word blurred (RT_LetterBlur): its light spread over the word's box widened
// by half the capital height on every side, at the share of the box its letters light
// (RT_LetterInk, 0.45: PHARMACY as the road sees it). In a perfect mirror the copy must carry the
// light of the letters mirrored as they are (RT_LetterBlur 0), within 5 %, spread: the pixels it
// lights past a hundredth of the letters' brightest at least 1.5 times as many, its brightest below
// theirs. Measured: 1.04 of the light, 3.9 times the pixels, 0.44 of the peak. The wet road's
// relief then breaks the word's mirror image into soft dashes of varied brightness instead of the
// letters' sharp strokes moved about ("sparse, one-pixel dots and dashes", blind viewers).
TEST(PovRayLettering, AMirrorSeesALitWordBlurredWithItsLightKept) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_word_blur");
  const std::string options = testing::square_size(kLetteringPixels) + " +A0.01 +AM2 +R3";
  const auto sharp = testing::trace_linear(dir, "sharp", mirrored_word_scene("0"), options);
  const auto blurred = testing::trace_linear(dir, "blurred", mirrored_word_scene(""), options);
  const auto none = testing::trace_linear(dir, "none", mirrored_word_scene("", false), options);
  ASSERT_EQ(sharp.size(), 3u * kLetteringPixels * kLetteringPixels);
  ASSERT_EQ(blurred.size(), sharp.size());
  ASSERT_EQ(none.size(), sharp.size());
  const testing::LightSpread spread = testing::light_spread(sharp, blurred, none);
  ASSERT_GT(spread.sharp_light, 0.0) << "the mirror shows no word";
  std::printf(
      "a mirrored word's blurred copy: %.4f of its letters' light, %d pixels against %d, "
      "peak %.3f\n",
      spread.light_ratio, spread.blurred_lit, spread.sharp_lit, spread.peak_ratio);
  EXPECT_NEAR(spread.light_ratio, 1.0, 0.05);
  EXPECT_GE(spread.blurred_lit, 1.5 * spread.sharp_lit) << "the copy is not spread";
  EXPECT_LT(spread.peak_ratio, 1.0) << "the copy is as bright as the letters";
  fs::remove_all(dir);
}

// A lit word 10 m from the camera, seen 45° off its fascia's normal, in mist of scattering
// coefficient `haze` (RT_LampHaze), with its halo (RT_SignHalos), the word moved into the
// street's coordinates as RT_Terrace moves it: the fascia at x = 7 facing the street's middle,
// a black wall behind the letters (a sheet through the word would pass into it and lose half the
// halo: the sheet must stand in the street's air).
std::string hazy_word_scene(double haze, bool word = true) {
  return "#version 3.7;\n"
         "global_settings { assumed_gamma 1 max_trace_level 10 }\n"
         "#declare RT_CameraPosition = <-0.201, 3.375, 6.929>;\n"
         "#declare RT_LightsOnly = 1;\n"
         "#declare RT_LampHaze = " +
         std::to_string(haze) +
         ";\n"
         "#include \"night_street.inc\"\n"
         "#declare RT_Side = 1;\n"
         "camera { perspective location RT_CameraPosition look_at <6.87, 3.375, 14> angle 44 }\n"
         "box { <6.95, -10, -30>, <9, 20, 60> pigment { rgb 0 } finish { ambient 0 diffuse 0 } "
         "}\n" +
         std::string(word
                         ? "union { RT_Lettering(\"KEBAB HOUSE\", 12, 16, 3.05, 3.7, <1, 1, 1>, 1) "
                           "translate 7 * x }\n"
                           "#declare RT_SignCentre[0] = RT_SignCentre[0] + 7 * x;\n"
                           "RT_SignHalos()\n"
                         : "");
}

// The mist takes a share σ·D of a sign's light out of its way to a camera D off and sends it on
// within a few degrees: the halo's light, summed over the picture, must be about that share of
// the word's own (for the two lobes, each half of the scattering, about 0.75 of it falls within
// the halo's reach), between 0.5 and 1.2 times σ·D; in twice the mist, twice as much (within 5 %).
// Measured: 0.779 σ·D at σ = 0.01 /m, 2.01 times in 0.02 (0.774 and 2.02 while each point's
// halo was flat within its softening radius); 0.318 while each point's halo was cut off within
// that radius instead of keeping its light there, and about 0.38 (a reviewer's run) with the
// sheet through the word instead of pulled toward the camera, the wall taking half.
TEST(PovRayLettering, ALitWordsHaloInTheMistIsTheLightTheMistScattersOutOfItsWay) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_word_halo");
  const std::string options = testing::square_size(kLetteringPixels) + " +A0.01 +AM2 +R3";
  const auto clear = testing::trace_linear(dir, "clear", hazy_word_scene(0.0), options);
  const auto misty = testing::trace_linear(dir, "misty", hazy_word_scene(0.01), options);
  const auto mistier = testing::trace_linear(dir, "mistier", hazy_word_scene(0.02), options);
  const auto none = testing::trace_linear(dir, "none", hazy_word_scene(0.0, false), options);
  ASSERT_EQ(clear.size(), 3u * kLetteringPixels * kLetteringPixels);
  ASSERT_EQ(misty.size(), clear.size());
  ASSERT_EQ(mistier.size(), clear.size());
  ASSERT_EQ(none.size(), clear.size());
  double word = 0.0, halo = 0.0, halo_twice = 0.0;
  for (std::size_t i = 1; i < clear.size(); i += 3) {  // green
    word += clear[i] - none[i];
    halo += misty[i] - clear[i];
    halo_twice += mistier[i] - clear[i];
  }
  ASSERT_GT(word, 0.0) << "no word";
  const double share = halo / word / (0.01 * 10.0);
  std::printf("a word's halo: %.3f of sigma*D of its light; %.3f times that in twice the mist\n",
              share, halo_twice / halo);
  EXPECT_GT(share, 0.5) << "the halo is fainter than the light the mist scatters";
  EXPECT_LT(share, 1.2) << "the halo holds more light than the mist scatters";
  EXPECT_NEAR(halo_twice / halo, 2.0, 0.1);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace raintrace::povgen
