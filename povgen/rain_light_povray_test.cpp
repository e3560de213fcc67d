// The rain's light measured in real POV-Ray renders (ctest label `povray`; skipped without
// povray), against the radiometry of docs/rain-appearance.md: a streak replaces, over the share
// of the exposure its drop covers each point, what lies behind by the drop's radiance; so the
// light rain adds does not depend on the exposure, rain nothing lights is invisible, one drop's
// streak carries its drop's area of coverage, and a near drop is spread over its path.
// Renders are OpenEXR (+FE): the light of faint streaks is far below 8-bit PNG's 1/255.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "povgen/drop_shape.h"
#include "povgen/frame_text.h"
#include "povgen/frame_values.h"
#include "povgen/output_folder.h"
#include "povgen/povray_test_support.h"
#include "povgen/streak_atlas.h"
#include "sim/terminal_velocity.h"

namespace raintrace::povgen {
namespace {

namespace fs = std::filesystem;
using testing::log_of;
using testing::read_rgb;
using testing::run_povray;

/// A test environment: a uniform background, RT_RainSurround, optionally one light and a
/// checkered backdrop, and nothing else (RT_KeyLight for the lightning light).
struct Environment {
  double background = 0.0;
  double surround = -1.0;  ///< < 0: not declared (scene.inc's fallback, black)
  bool backlight = false;  ///< a point light 6 m behind the rain, above the camera's line
  bool backdrop = false;   ///< a matte checkered wall at z = 3 lit by `background` as ambient
};

std::string environment_text(const Environment& e) {
  std::string text = "#declare RT_KeyLight = 1;\n";
  text += "background { rgb " + std::to_string(e.background) + " }\n";
  if (e.surround >= 0.0) {
    text += "#declare RT_RainSurround = rgb " + std::to_string(e.surround) + ";\n";
  }
  if (e.backlight) {
    text += "light_source { <0.3, 2.4, 8> color rgb 4 }\n";
  }
  if (e.backdrop) {
    text +=
        "plane { -z, -3 hollow pigment { checker rgb 0.1 rgb 0.3 scale 0.05 } "
        "finish { ambient 0 diffuse 0 emission 1 } }\n";
  }
  return text;
}

/// One rain drop for the frame: position, velocity, diameter.
struct Drop {
  glm::vec3 position;
  glm::vec3 velocity;
  float diameter;
};

sim::Frame frame_of(const std::vector<Drop>& drops) {
  sim::Frame frame;
  frame.index = 1;
  for (const Drop& d : drops) {
    frame.drops.id.push_back(frame.drops.id.size());
    frame.drops.position.push_back(d.position);
    frame.drops.velocity.push_back(d.velocity);
    frame.drops.acceleration.push_back(glm::vec3{0.0f});
    frame.drops.diameter.push_back(d.diameter);
    frame.drops.age.push_back(0.0f);
    frame.drops.vanishing_rate.push_back(0.0f);
    frame.drops.opacity.push_back(1.0f);
    frame.drops.colour.push_back(glm::vec3{1.0f});
  }
  return frame;
}

/// Exports the drops into a fresh folder with the environment as the user's include, renders
/// the frame and the same frame without rain, and returns (rain, rain-free) pixels.
struct Renders {
  std::vector<float> rain;
  std::vector<float> bare;
};

Renders render(const std::string& name, ExportParams look, const Environment& environment,
               const std::vector<Drop>& drops) {
  const fs::path dir = testing::empty_scratch_folder("rain_light_test_" + name);
  write_file_atomic(dir / "environment_source.inc", environment_text(environment));
  look.environment.include_path = "environment_source.inc";
  look.rain_medium = false;  // only the streaks and drops are measured here
  write_shared_files(dir, look, 1, dir, {1, 1});
  write_file_atomic(dir / "frames" / "frame_0001.pov",
                    frame_text(build_frame_values(frame_of(drops), look)));
  write_file_atomic(dir / "frames" / "bare.pov", "#declare RT_Flash=0;\n#include \"scene.inc\"\n");
  const std::string size = " +W" + std::to_string(look.width) + " +H" +
                           std::to_string(look.height) + " +FE -A +L. +WT1 ";
  Renders out;
  EXPECT_EQ(run_povray(dir, "frames/frame_0001.pov" + size + "+Oimages/rain.exr"), 0)
      << name << "\n"
      << log_of(dir);
  EXPECT_EQ(run_povray(dir, "frames/bare.pov" + size + "+Oimages/bare.exr"), 0) << name << "\n"
                                                                                << log_of(dir);
  out.rain = read_rgb(dir / "images" / "rain.exr");
  out.bare = read_rgb(dir / "images" / "bare.exr");
  EXPECT_EQ(out.rain.size(), static_cast<std::size_t>(look.width) * look.height * 3) << name;
  EXPECT_EQ(out.rain.size(), out.bare.size()) << name;
  fs::remove_all(dir);
  return out;
}

/// Σ (rain − bare) over the pixels of the green channel: the light the rain adds.
double added_light(const Renders& r) {
  double sum = 0.0;
  for (std::size_t i = 1; i < std::min(r.rain.size(), r.bare.size()); i += 3) {
    sum += r.rain[i] - r.bare[i];
  }
  return sum;
}

/// Pixels where rain and bare differ by more than `threshold` (green channel).
std::size_t touched_pixels(const Renders& r, double threshold = 1e-6) {
  std::size_t n = 0;
  for (std::size_t i = 1; i < std::min(r.rain.size(), r.bare.size()); i += 3) {
    n += std::fabs(r.rain[i] - r.bare[i]) > threshold ? 1 : 0;
  }
  return n;
}

/// How far apart the light two renders of the same `streaks` rain add may lie. Without
/// antialiasing each streak is sampled at pixel centres: the light it adds is its area in
/// pixels ± about one pixel per row it crosses, independently for each streak, so the relative
/// error of the sum is about 1/√(pixels touched) per render; the atlas rows round each streak's
/// opacity to within 2^(±1/16) (4.4 %), spread as a uniform error of σ 2.5 % that averages to
/// 2.5 %/√N over N streaks, and biased by +0.1 % (the mean of 2^δ). Three σ of both renders and
/// the bias.
double same_light_tolerance(const Renders& a, const Renders& b, std::size_t streaks) {
  const double sampling = std::sqrt(1.0 / static_cast<double>(touched_pixels(a)) +
                                    1.0 / static_cast<double>(touched_pixels(b)));
  const double rounding = 0.025 * std::sqrt(2.0 / static_cast<double>(streaks));
  return 0.001 + 3.0 * std::hypot(sampling, rounding);
}

ExportParams small_look(int width, int height) {
  ExportParams look;
  look.width = width;
  look.height = height;
  look.camera.look_at = {0.0, 1.6, 0.0};  // level: rain falls across the view
  return look;
}

/// `count` drops of 0.5–3 mm at terminal speed, 2 to 4 m deep, spread over the view and 0.6 m
/// above it (every streak that leaves the bottom of the picture during the exposure is
/// balanced by one entering at the top, whatever the exposure). Deterministic.
std::vector<Drop> rain_slab(int count, const ExportParams& look) {
  std::vector<Drop> drops;
  std::uint32_t state = 2024;
  auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) * 0x1.0p-24f;
  };
  const double aspect = static_cast<double>(look.width) / look.height;
  const auto tan_x = static_cast<float>(std::tan(look.camera.fov_deg * std::numbers::pi / 360.0));
  const auto tan_y = static_cast<float>(tan_x / aspect);
  for (int i = 0; i < count; ++i) {
    const float depth = 2.0f + 2.0f * next();
    const float x = (2.0f * next() - 1.0f) * depth * tan_x;
    // Evenly from the bottom of the view to 0.6 m above its top: as many streaks enter at the
    // top as leave at the bottom. (The sum of two draws made the bottom 0.6 m sparser, so a
    // longer exposure let more light in than out: 4.5 % more at 0.04 s than at 0.01 s, once
    // every streak carried its drop's area.)
    const float half_height = depth * tan_y;
    const float y = 1.6f - half_height + (2.0f * half_height + 0.6f) * next();
    const float diameter = (0.5f + 2.5f * next()) * 1e-3f;
    const auto speed = static_cast<float>(sim::terminal_velocity(diameter));
    drops.push_back({{x, y, -5.0f + depth}, {0.0f, -speed, 0.0f}, diameter});
  }
  return drops;
}

TEST(PovRayRainLight, TheSameRainAddsTheSameLightAtEveryExposure) {
  SKIP_WITHOUT_POVRAY();
  // Backlit rain over black; every streak kept (min_streak_coverage 0; the atlas's floor,
  // ~1.6e-4, is below every streak here: 0.5 mm at 2 m/s over 0.04 s and 4 m, 320 px: coverage
  // 0.5/80 × 0.5/14.4 = 2.2e-4).
  ExportParams look = small_look(320, 180);
  look.min_streak_coverage = 0.0;
  const std::vector<Drop> drops = rain_slab(3000, look);
  Environment environment;
  environment.backlight = true;
  environment.surround = 0.02;
  look.camera.exposure_s = 0.01;
  const Renders short_exposure = render("exposure_short", look, environment, drops);
  look.camera.exposure_s = 0.04;
  const Renders long_exposure = render("exposure_long", look, environment, drops);
  const double a = added_light(short_exposure);
  const double b = added_light(long_exposure);
  ASSERT_GT(a, 0.0);
  const double tolerance = same_light_tolerance(short_exposure, long_exposure, drops.size());
  EXPECT_NEAR(b / a, 1.0, tolerance) << "added light " << a << " at 0.01 s, " << b << " at 0.04 s";
  ::testing::Test::RecordProperty("ratio", std::to_string(b / a));
  ::testing::Test::RecordProperty("tolerance", std::to_string(tolerance));
  // Before issue 12 the longer exposure added 3.3× the light: the test must be able to fail.
  EXPECT_LT(tolerance, 0.1);
}

TEST(PovRayRainLight, RainOutOfFocusAddsTheSameLightAsInFocus) {
  SKIP_WITHOUT_POVRAY();
  // The slab 2–4 m deep, a lens 5 cm open focused 20 m away, the rain alone blurred: every drop
  // spreads over a disc of 0.05·(16…18)/20 = 40–45 mm, about four pixels at 320 px (a pixel is
  // 10.8 mm at 3 m), so the sub-pixel streaks become resolved ones four times as wide and a
  // sixteenth as opaque. Defocus moves light, it adds none.
  ExportParams look = small_look(320, 180);
  look.min_streak_coverage = 0.0;
  look.camera.look_at = {0.0, 1.6, 15.0};
  const std::vector<Drop> drops = rain_slab(3000, look);
  Environment environment;
  environment.backlight = true;
  environment.surround = 0.02;
  const Renders sharp = render("focus_sharp", look, environment, drops);
  look.aperture_m = 0.05;
  look.focal_blur = FocalBlur::rain;
  const Renders blurred = render("focus_blurred", look, environment, drops);
  const double a = added_light(sharp);
  const double b = added_light(blurred);
  ASSERT_GT(a, 0.0);
  // The blur does show: it touches more pixels.
  EXPECT_GT(touched_pixels(blurred), 2 * touched_pixels(sharp));
  // Plus the light of the streaks within two pixels of the left and right edges, half of which
  // the wider streaks carry out of the picture: 2·2/320 of the drops, at most half each, 0.7 %.
  const double tolerance = 0.007 + same_light_tolerance(sharp, blurred, drops.size());
  EXPECT_NEAR(b / a, 1.0, tolerance) << "added light " << a << " sharp, " << b << " blurred";
  ::testing::Test::RecordProperty("ratio", std::to_string(b / a));
  ::testing::Test::RecordProperty("tolerance", std::to_string(tolerance));
  EXPECT_LT(tolerance, 0.1);
}

TEST(PovRayRainLight, RainWithNoLightIsInvisible) {
  SKIP_WITHOUT_POVRAY();
  // Black surroundings, no light, no RT_RainSurround: streaks, and refractive spheres (exposure
  // 0 keeps near drops as drops), add nothing at all.
  ExportParams look = small_look(160, 90);
  look.min_streak_coverage = 0.0;
  const std::vector<Drop> drops = rain_slab(2000, look);
  for (const double exposure : {0.0, 0.02}) {
    look.camera.exposure_s = exposure;
    std::vector<Drop> near = drops;
    near.push_back({{0.0f, 1.6f, -4.2f}, {0.0f, -6.0f, 0.0f}, 3e-3f});  // a sphere at 0.8 m
    const Renders r = render("dark", look, Environment{}, near);
    EXPECT_EQ(touched_pixels(r, 0.0), 0u) << "exposure " << exposure;
    EXPECT_EQ(added_light(r), 0.0);
  }
}

TEST(PovRayRainLight, OneDropsStreakCarriesTheDropsAreaOfItsRadiance) {
  SKIP_WITHOUT_POVRAY();
  // One 3 mm drop 1 m in front of the camera over a uniform background 0.05, refracting
  // surroundings of 0.45, no light: wherever the streak covers α of a pixel it shows
  // α·0.45 + (1 − α)·0.05, so Σ(rain − bare) = (0.45 − 0.05) × its coverage summed over the
  // pixels = 0.4 × the drop's silhouette in pixels, πab/p² (Garg & Nayar: whatever the
  // exposure). At 640 px a pixel 1 m away is 2·tan30°/640 = 1.8042 mm; Beard-Chuang flattens a
  // 3 mm drop to ratio 0.85582: a = 1.57992 mm, b = 1.35213 mm, πab = 6.7113 mm² = 2.0618 px².
  // The drop travels about 8 and 32 of its heights (2b = 2.70426 mm), the middle opacity
  // 1/travel; exactly so much that this opacity times its atlas column's gain is a row of the
  // atlas, so the rows' rounding (up to 4.4 %) does not enter.
  ExportParams look = small_look(640, 360);
  look.min_streak_coverage = 0.0;
  look.sphere_distance_m = 0.0;
  look.camera.exposure_s = 0.01;
  Environment environment;
  environment.background = 0.05;
  environment.surround = 0.45;
  const double height = 2.70426e-3;
  const double expected = 0.4 * std::numbers::pi * 1.57992 * 1.35213 / (1.80422 * 1.80422);
  // Sampling at pixel centres without antialiasing: a streak 1.75 px wide lands 1 or 2 pixel
  // centres per row, and which depends on where it falls within a pixel. Eight drops
  // 10 + 1/8 px apart (across) and 1/8 px apart in height sample every such offset evenly:
  // the sum is then within the bilinear filter's error, and the column's profile (drawn for a
  // motion of 8 or 32 heights over a travel a few % off): 2 %.
  const float pixel = 1.80422e-3f;
  const StreakAtlasLayout atlas;
  for (const double heights : {8.0, 32.0}) {
    const int column = heights < 16.0 ? 5 : 7;  // motion 8 and 32, resolved
    const double gain = streak_atlas_column_gain(atlas, column);
    const double row_opacity =
        atlas.row_opacity(static_cast<int>(std::lround(-8.0 * std::log2(gain / heights))));
    const auto speed = static_cast<float>(gain / row_opacity * height / look.camera.exposure_s);
    std::vector<Drop> drops;
    for (int k = 0; k < 8; ++k) {
      const float offset = static_cast<float>(k) * (10.0f + 0.125f) * pixel;
      drops.push_back({{-0.04f + offset, 1.7f + 0.125f * pixel * static_cast<float>(k), -4.0f},
                       {0.0f, -speed, 0.0f},
                       3e-3f});
    }
    const Renders r = render("one_drop", look, environment, drops);
    EXPECT_NEAR(added_light(r) / (8.0 * expected), 1.0, 0.02) << heights << " heights";
    ::testing::Test::RecordProperty("ratio_" + std::to_string(static_cast<int>(heights)),
                                    std::to_string(added_light(r) / (8.0 * expected)));
  }
}

/// Rows of the image that rain changed: the first and last (−1, −1 if none).
std::pair<int, int> touched_rows(const Renders& r, int width, double threshold) {
  int first = -1;
  int last = -1;
  for (std::size_t i = 1; i < std::min(r.rain.size(), r.bare.size()); i += 3) {
    if (std::fabs(r.rain[i] - r.bare[i]) <= threshold) continue;
    const int row = static_cast<int>(i / 3) / width;
    if (first < 0) first = row;
    last = row;
  }
  return {first, last};
}

TEST(PovRayRainLight, NearDropsAreBlurredOverTheDistanceTheyTravel) {
  SKIP_WITHOUT_POVRAY();
  // A 4 mm drop falling at 8.8 m/s, 1 m from the camera, in front of a checkered wall that its
  // refraction turns upside down. At 640 px a pixel 1 m away is 1.8042 mm; the drop is
  // 2b = 3.3874 mm = 1.9 px high. Exposure 0: a sharp drop, ~2 rows. 10 ms: it falls 88 mm =
  // 48.8 px, and shows over its path and height: 48.8 + 1.9 = 50.7 rows.
  ExportParams look = small_look(640, 360);
  look.min_streak_coverage = 0.0;
  Environment environment;
  environment.background = 0.05;
  environment.surround = 0.9;
  environment.backdrop = true;
  const std::vector<Drop> drop{{{0.0f, 1.65f, -4.0f}, {0.0f, -8.8f, 0.0f}, 4e-3f}};
  look.camera.exposure_s = 0.0;
  const auto [sharp_top, sharp_bottom] =
      touched_rows(render("near_sharp", look, environment, drop), look.width, 1e-3);
  ASSERT_GE(sharp_top, 0) << "the drop is not in the picture";
  EXPECT_LE(sharp_bottom - sharp_top + 1, 3);
  look.camera.exposure_s = 0.01;
  const auto [top, bottom] =
      touched_rows(render("near_blurred", look, environment, drop), look.width, 1e-3);
  ASSERT_GE(top, 0);
  EXPECT_NEAR(bottom - top + 1, 50.7, 2.0);
  // It starts where the sharp drop is: the shutter opens at the frame's time.
  EXPECT_NEAR(top, sharp_top, 1.0);
}

}  // namespace
}  // namespace raintrace::povgen
