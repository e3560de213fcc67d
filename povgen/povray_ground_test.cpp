// The wet ground rendered by the real POV-Ray (ctest label `povray`; skipped without povray):
// ripples appear in the picture where their impacts were simulated and spread with time, the
// rain's unresolved roughness does not alias into glints without antialiasing, a puddle shows
// the ground beneath it and covers the paint on it, its shoreline is ragged, and splashes carry
// on past the simulated volume of drops without an edge.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "povgen/frame_text.h"
#include "povgen/frame_values.h"
#include "povgen/ground_maps.h"
#include "povgen/output_folder.h"
#include "povgen/povray_test_support.h"
#include "sim/ripples.h"
#include "sim/world.h"

namespace raintrace::povgen {
namespace {

namespace fs = std::filesystem;
using testing::log_of;
using testing::read_rgb;
using testing::run_povray;

/// A wet ground plane (RT_WetGround over a dark asphalt) under a sky of smooth bright and dark
/// horizontal bands, so that a tilt of the water changes the colour it mirrors in proportion.
constexpr const char* kWetPlane = R"(
#declare Dry = texture { pigment { rgb 0.02 } finish { ambient 0 diffuse 0.2 } }
plane { y, 0
#ifdef (RT_WetGround)
  texture { RT_WetGround(Dry) }
#else
  texture { Dry }
#end
  interior { ior 1.33 }
}
sky_sphere { pigment { gradient y triangle_wave color_map { [0 rgb 0.02] [1 rgb 3] } scale 0.04 } }
light_source { <0, 50, 0> color rgb 0.2 }
)";

/// The same wet plane under a sky whose brightness grows in proportion to the height of the
/// direction (0 at the horizon, 10 overhead): what a tilted patch of water mirrors changes
/// linearly with its tilt, so the picture's departure from calm water maps the water's slopes.
constexpr const char* kWetPlaneLinearSky = R"(
#declare Dry = texture { pigment { rgb 0.02 } finish { ambient 0 diffuse 0.2 } }
plane { y, 0
  texture { RT_WetGround(Dry) }
  interior { ior 1.33 }
}
sky_sphere { pigment { gradient y color_map { [0 rgb 0] [1 rgb 10] } } }
)";

/// Calm puddles on a plain ground that is their bed too, under a black sky, lit by a distant
/// light behind and above the camera (its mirror highlight points away): all the light that
/// comes back is diffuse, from the ground or from the bed through the water's surface.
/// Declare=NoBed=1 leaves RT_PuddleBed undeclared.
constexpr const char* kPlainGroundUnderWater = R"(
#declare Ground = pigment { rgb 0.05 }
#ifndef (NoBed) #declare RT_PuddleBed = pigment { Ground } #end
#declare Dry = texture { pigment { Ground } finish { ambient 0 diffuse 0.55 } }
plane { y, 0
  texture { RT_WetGround(Dry) }
  interior { ior 1.33 }
}
sky_sphere { pigment { rgb 0 } }
light_source { <0, 9000, -5000> color rgb 1 parallel point_at 0 }
)";

/// Puddles on a black ground under a uniform white sky, with no light: the water shows the sky
/// it mirrors (2 % of it head-on, more at grazing angles), the dry ground nothing at all.
constexpr const char* kWaterUnderWhiteSky = R"(
#declare Dry = texture { pigment { rgb 0 } finish { ambient 0 diffuse 0 } }
plane { y, 0
  texture { RT_WetGround(Dry) }
  interior { ior 1.33 }
}
sky_sphere { pigment { rgb 1 } }
)";

/// kWaterUnderWhiteSky with a strip of glowing paint, a metre wide, laid on the road along the
/// view (RT_WetGroundOver, over a black bed): dry, the paint glows; in a puddle its water
/// covers it and mirrors the sky as the water beside it does.
constexpr const char* kPaintUnderWhiteSky = R"(
#declare Dry = texture { pigment { rgb 0 } finish { ambient 0 diffuse 0 } }
plane { y, 0
  texture { RT_WetGround(Dry) }
  interior { ior 1.33 }
}
#declare Paint = texture { pigment { rgb 1 } finish { ambient 0.3 diffuse 0 } }
box { <-0.5, 0, -4>, <0.5, 0.002, 60>
  texture { RT_WetGroundOver(Paint, pigment { rgb 0 }) }
  interior { ior 1.33 }
}
sky_sphere { pigment { rgb 1 } }
)";

/// The view of the puddle tests: the road from 1.6 m up, looking down to a point 10 m ahead,
/// 16:9 at `width` pixels.
ExportParams road_view(int width) {
  ExportParams look;
  look.width = width;
  look.height = width * 9 / 16;
  look.camera.position = {0.0, 1.6, -4.0};
  look.camera.look_at = {0.0, 0.0, 6.0};
  look.camera.fov_deg = 40.0;
  return look;
}

/// road_view over calm puddles: no rain (no rings, no roughness, no rain medium), standing
/// water on `coverage` of the road in patches of about `size_m`.
ExportParams calm_puddles(int width, double coverage, double size_m) {
  ExportParams look = road_view(width);
  look.ground.puddles.coverage = coverage;
  look.ground.puddles.size_m = size_m;
  look.rain.rate_mm_per_h = 0.0;
  look.rain_medium = false;
  return look;
}

/// A folder whose environment is `environment` (kWetPlane unless given), with frames 1..n from
/// `frames`.
fs::path wet_folder(const std::string& name, const ExportParams& base,
                    const std::vector<sim::Frame>& frames, const char* environment = kWetPlane) {
  const fs::path dir = testing::empty_scratch_folder("povray_ground_" + name);
  std::ofstream(dir / "wet.inc") << environment;
  ExportParams look = base;
  look.environment.include_path = "wet.inc";
  const std::string shared = write_shared_files(dir, look, static_cast<int>(frames.size()), dir,
                                                {1, static_cast<int>(frames.size())});
  FrameValues values;
  for (const sim::Frame& frame : frames) {
    build_frame_values(frame, look, values);
    write_frame_file(dir / "frames" / frame_file_name("frame", frame.index, 4, ".pov"), values,
                     shared, 1);
  }
  return dir;
}

/// A folder with one frame of `look` (no drops) over `environment`.
fs::path still_folder(const std::string& name, const ExportParams& look, const char* environment) {
  std::vector<sim::Frame> frames(1);
  frames[0].index = 1;
  return wet_folder(name, look, frames, environment);
}

/// Frame 1 of `dir` rendered without antialiasing, as linear RGB (empty, with a failure naming
/// POV-Ray's log, if it did not render).
std::vector<float> render_still(const fs::path& dir) {
  if (run_povray(dir, "scene.ini +SF1 +EF1 -A") != 0) {
    ADD_FAILURE() << log_of(dir);
    return {};
  }
  return read_rgb(dir / "images" / "frame_0001.exr");
}

TEST(PovRayGround, RipplesAppearWhereTheirImpactsWereAndSpreadWithTime) {
  SKIP_WITHOUT_POVRAY();
  // The camera 1.6 m up looks at the ground 2.5 m ahead (a pixel spans ~2.5 mm there at 1280
  // pixels, so the 31 mm rings are drawn), all of it puddle, no rain roughness. A 4 mm drop's
  // ring 0.1 s and 0.2 s after its impact, against the same frame without it.
  ExportParams look;
  look.width = 1280;
  look.height = 720;
  look.camera.position = {0.0, 1.6, -1.0};
  look.camera.look_at = {0.0, 0.0, 1.5};
  look.ground.puddles.coverage = 0.9;
  look.ground.puddles.size_m = 20.0;
  look.rain.rate_mm_per_h = 0.0;
  // A point deep in a puddle, near the middle of the view.
  const sim::PuddleField field(look.ground.puddles, look.ground.puddles.seed);
  double x0 = 0.0;
  while (field.value(x0, 1.5) < field.threshold() + 1.0) x0 += 0.25;
  look.camera.position.x = look.camera.look_at.x = x0;
  const glm::vec3 impact{static_cast<float>(x0), 0.0f, 1.5f};
  std::vector<sim::Frame> frames(3);
  for (int n = 0; n < 3; ++n) {
    frames[n].index = n + 1;
    frames[n].time_s = 0.1 * (n + 1);
    if (n < 2)
      frames[n].ripples.push_back(sim::make_ripple(impact, 4e-3f, 0.1 * (n + 1), 6e-3, true, 0.5));
  }
  const fs::path dir = wet_folder("rings", look, frames);
  for (int n = 1; n <= 3; ++n) {
    ASSERT_EQ(run_povray(dir, "scene.ini +SF" + std::to_string(n) + " +EF" + std::to_string(n)), 0)
        << log_of(dir);
  }
  // POV-Ray writes the frames as scene-linear OpenEXR (scene.ini's Output_File_Type=E).
  const auto flat = read_rgb(dir / "images" / "frame_0003.exr");
  ASSERT_FALSE(flat.empty()) << "no frame_0003.exr in " << dir;
  const GroundPixels pixels(look.camera, look.width, look.height, 0.0);
  double column = 0.0, row = 0.0;
  ASSERT_TRUE(pixels.project(impact.x, impact.z, column, row));
  // Where the picture changed, weighted by the change: its centre on screen, and the radius on
  // the ground within which 90 % of the change lies (the outer edge of the ring's packet of
  // crests, which keeps its shape as it moves out; within 12 cm of the impact, beyond its reach).
  auto changes = [&](int n, double& centre_column, double& centre_row, double& radius) {
    const auto px = read_rgb(dir / "images" / frame_file_name("frame", n, 4, ".exr"));
    ASSERT_EQ(px.size(), flat.size());
    double weight = 0.0, sum_c = 0.0, sum_r = 0.0;
    std::vector<std::pair<double, double>> by_distance;
    for (int j = 0; j < look.height; ++j) {
      for (int i = 0; i < look.width; ++i) {
        const std::size_t p = static_cast<std::size_t>(j) * look.width + i;
        if (!pixels.hits(p)) continue;
        const double distance = std::hypot(pixels.x(p) - impact.x, pixels.z(p) - impact.z);
        const double d = std::abs(px[3 * p] - flat[3 * p]);
        if (distance > 0.12 || d == 0.0) continue;
        weight += d;
        sum_c += d * (i + 0.5);
        sum_r += d * (j + 0.5);
        by_distance.emplace_back(distance, d);
      }
    }
    ASSERT_GT(weight, 1.0) << "frame " << n << ": no ripple to see";
    centre_column = sum_c / weight;
    centre_row = sum_r / weight;
    std::sort(by_distance.begin(), by_distance.end());
    double within = 0.0;
    for (const auto& [distance, d] : by_distance) {
      within += d;
      radius = distance;
      if (within >= 0.9 * weight) break;
    }
  };
  double c1 = 0.0, r1 = 0.0, radius1 = 0.0, c2 = 0.0, r2 = 0.0, radius2 = 0.0;
  changes(1, c1, r1, radius1);
  changes(2, c2, r2, radius2);
  // The ring is centred on its impact's pixel (seen at a slant, its nearer side covers more
  // pixels: within 3) …
  EXPECT_NEAR(c1, column, 3.0);
  EXPECT_NEAR(r1, row, 3.0);
  EXPECT_NEAR(c2, column, 3.0);
  EXPECT_NEAR(r2, row, 3.0);
  // … and spreads at the ring's group velocity, 0.184 m/s: 1.8 cm in 0.1 s (to a
  // quarter wavelength: the crests' reflections move in steps as they pass the sky's bands).
  EXPECT_NEAR(radius2 - radius1, sim::ripple_speed() * 0.1, 0.0045);
  fs::remove_all(dir);
}

TEST(PovRayGround, UnresolvedRoughnessDoesNotAliasIntoGlints) {
  SKIP_WITHOUT_POVRAY();
  // Puddles 4–12 m ahead of a camera 1.6 m up, at 320×180: a pixel spans 14–44 mm of ground
  // there, about the rings' 31 mm wavelength, so the rain's roughness is drawn by the noise. The
  // same frame of calm water (no rain) is the reference; the difference maps what the roughness
  // does to the reflection. One sample a pixel (-A), as at quality preview: the noise as drawn must
  // be resolved — neighbouring pixels tilted alike — where the true scale (RT_NoiseSpans = 0)
  // decorrelates them into a salt of glints; and it must still disturb the mirror.
  ExportParams look = road_view(320);
  look.ground.puddles.coverage = 0.9;
  look.ground.puddles.size_m = 20.0;
  look.rain_medium = false;  // the rain's roughness alone makes the difference
  const sim::PuddleField field(look.ground.puddles, look.ground.puddles.seed);
  std::vector<sim::Frame> frames(1);
  frames[0].index = 1;
  frames[0].time_s = 0.5;
  ExportParams calm = look;
  calm.rain.rate_mm_per_h = 0.0;
  look.rain.rate_mm_per_h = 20.0;
  const fs::path calm_dir = wet_folder("calm", calm, frames, kWetPlaneLinearSky);
  const fs::path rain_dir = wet_folder("rough", look, frames, kWetPlaneLinearSky);
  ASSERT_EQ(run_povray(calm_dir, "scene.ini +SF1 +EF1 -A"), 0) << log_of(calm_dir);
  ASSERT_EQ(run_povray(rain_dir, "scene.ini +SF1 +EF1 -A Declare=RT_Preview=1 +Oimages/drawn"), 0)
      << log_of(rain_dir);
  ASSERT_EQ(run_povray(rain_dir,
                       "scene.ini +SF1 +EF1 -A Declare=RT_Preview=1 "
                       "Declare=RT_NoiseSpans=0 +Oimages/true_scale"),
            0)
      << log_of(rain_dir);
  const auto reference = read_rgb(calm_dir / "images" / "frame_0001.exr");
  const auto drawn = read_rgb(rain_dir / "images" / "drawn0001.exr");
  const auto true_scale = read_rgb(rain_dir / "images" / "true_scale0001.exr");
  ASSERT_FALSE(reference.empty());
  ASSERT_EQ(drawn.size(), reference.size());
  ASSERT_EQ(true_scale.size(), reference.size());
  // Pixels deep inside a puddle (their right and lower neighbours too) seeing 4–12 m ahead.
  const GroundPixels pixels(look.camera, look.width, look.height, 0.0);
  auto usable = [&](std::size_t p) {
    return pixels.hits(p) && pixels.z(p) > 0.0 && pixels.z(p) < 8.0 &&
           field.value(pixels.x(p), pixels.z(p)) > field.threshold() + 0.3;
  };
  // Rms departure from calm water, and its correlation between neighbouring pixels.
  auto measure = [&](const std::vector<float>& image, double& rms, double& correlation) {
    double sum_sq = 0.0, sum_next = 0.0;
    int count = 0;
    for (int j = 0; j + 1 < look.height; ++j) {
      for (int i = 0; i + 1 < look.width; ++i) {
        const std::size_t p = static_cast<std::size_t>(j) * look.width + i;
        const std::size_t right = p + 1, below = p + look.width;
        if (!usable(p) || !usable(right) || !usable(below)) continue;
        const double d = image[3 * p] - reference[3 * p];
        sum_sq += d * d;
        sum_next +=
            d * 0.5 *
            ((image[3 * right] - reference[3 * right]) + (image[3 * below] - reference[3 * below]));
        ++count;
      }
    }
    ASSERT_GT(count, 2000) << "too few puddle pixels";
    ASSERT_GT(sum_sq, 0.0) << "the rain's roughness changed nothing";
    rms = std::sqrt(sum_sq / count);
    correlation = sum_next / sum_sq;
  };
  double rms_drawn = 0.0, corr_drawn = 0.0, rms_true = 0.0, corr_true = 0.0;
  measure(drawn, rms_drawn, corr_drawn);
  measure(true_scale, rms_true, corr_true);
  std::printf("as drawn: rms %.4f, correlation %.3f; true scale: rms %.4f, correlation %.3f\n",
              rms_drawn, corr_drawn, rms_true, corr_true);
  EXPECT_GT(corr_drawn, 0.4) << "as drawn: neighbours tilted independently (salt)";
  EXPECT_LT(corr_true, 0.2) << "true scale: the noise is no longer finer than a pixel";
  EXPECT_GT(rms_drawn, 0.1 * rms_true) << "as drawn: the roughness no longer shows";
  fs::remove_all(calm_dir);
  fs::remove_all(rain_dir);
}

// Standing water a few millimetres deep absorbs next to nothing and lies on ground as wet as the
// film around it: seen through its surface, a puddle is that ground (plus what it mirrors —
// here a black sky). Painted near black, as before, puddles read as holes cut in the street.
// (POV-Ray does not take the Fresnel share a surface reflects from its diffuse light —
// conserve_energy acts on transparency only — so the ground beside the puddles and the bed
// through the water match, as the wet road's own finish does.)
TEST(PovRayGround, PuddleShowsTheGroundBeneathItsSurface) {
  SKIP_WITHOUT_POVRAY();
  const ExportParams look = calm_puddles(320, 0.5, 1.0);
  const sim::PuddleField field(look.ground.puddles, look.ground.puddles.seed);
  const fs::path with_bed = still_folder("bed", look, kPlainGroundUnderWater);
  ASSERT_EQ(run_povray(with_bed, "scene.ini +SF1 +EF1 -A"), 0) << log_of(with_bed);
  // The same ground with no bed declared: the near-black default shows through.
  ASSERT_EQ(run_povray(with_bed, "scene.ini +SF1 +EF1 -A Declare=NoBed=1 +Oimages/no_bed"), 0)
      << log_of(with_bed);
  const auto image = read_rgb(with_bed / "images" / "frame_0001.exr");
  const auto black_bed = read_rgb(with_bed / "images" / "no_bed0001.exr");
  ASSERT_EQ(image.size(), static_cast<std::size_t>(3 * look.width * look.height));
  ASSERT_EQ(black_bed.size(), image.size());

  // Per row (one view angle), the mean of pixels well inside puddles against the mean of pixels
  // well outside them.
  const GroundPixels pixels(look.camera, look.width, look.height, 0.0);
  double ratio_sum = 0.0, black_ratio_sum = 0.0;
  int rows = 0;
  for (int j = 0; j < look.height; ++j) {
    double water = 0.0, water_black = 0.0, ground = 0.0;
    int n_water = 0, n_ground = 0;
    for (int i = 0; i < look.width; ++i) {
      const std::size_t p = static_cast<std::size_t>(j) * look.width + i;
      if (!pixels.hits(p) || pixels.z(p) > 30.0) continue;
      // Beyond the shorelines' band (sim::PuddleField::kFringeM), where the relief moves none.
      const double share = field.share(pixels.x(p), pixels.z(p));
      if (share >= 1.0) {
        water += image[3 * p + 1];
        water_black += black_bed[3 * p + 1];
        ++n_water;
      } else if (share <= 0.0) {
        ground += image[3 * p + 1];
        ++n_ground;
      }
    }
    if (n_water < 5 || n_ground < 5) continue;
    ratio_sum += (water / n_water) / (ground / n_ground);
    black_ratio_sum += (water_black / n_water) / (ground / n_ground);
    ++rows;
  }
  ASSERT_GT(rows, 40) << "too few rows with both puddle and dry ground";
  const double ratio = ratio_sum / rows, black_ratio = black_ratio_sum / rows;
  std::printf("puddle / ground: %.3f over %d rows; near-black bed: %.3f\n", ratio, rows,
              black_ratio);
  EXPECT_NEAR(ratio, 1.0, 0.05) << "the bed does not show through the water as it should";
  EXPECT_LT(black_ratio, 0.3) << "without RT_PuddleBed the puddles are no longer dark";
  fs::remove_all(with_bed);
}

// Road paint in a puddle lies under its water: it mirrors the street as the water beside it does
// (painted on top, a road marking read as a plank lying in the puddle).
TEST(PovRayGround, PaintInAPuddleLiesUnderItsWater) {
  SKIP_WITHOUT_POVRAY();
  const ExportParams look = calm_puddles(320, 0.5, 1.0);
  const sim::PuddleField field(look.ground.puddles, look.ground.puddles.seed);
  const fs::path dir = still_folder("paint", look, kPaintUnderWhiteSky);
  const auto image = render_still(dir);
  ASSERT_EQ(image.size(), static_cast<std::size_t>(3 * look.width * look.height));

  // Per row (one view angle), water over the paint against water beside it, well inside the
  // strip and well outside it; and the dry paint's glow.
  const GroundPixels pixels(look.camera, look.width, look.height, 0.0);
  double ratio_sum = 0.0, dry_paint = 0.0;
  int rows = 0, n_dry_paint = 0;
  for (int j = 0; j < look.height; ++j) {
    double on_paint = 0.0, beside = 0.0;
    int n_on_paint = 0, n_beside = 0;
    for (int i = 0; i < look.width; ++i) {
      const std::size_t p = static_cast<std::size_t>(j) * look.width + i;
      if (!pixels.hits(p) || pixels.z(p) > 30.0) continue;
      const double across = std::abs(pixels.x(p));
      const double share = field.share(pixels.x(p), pixels.z(p));
      const float green = image[3 * p + 1];
      if (share <= 0.0 && across < 0.4) {
        dry_paint += green;
        ++n_dry_paint;
      }
      if (share < 1.0) continue;
      if (across < 0.4) {
        on_paint += green;
        ++n_on_paint;
      } else if (across > 0.6) {
        beside += green;
        ++n_beside;
      }
    }
    if (n_on_paint < 3 || n_beside < 3) continue;
    ratio_sum += (on_paint / n_on_paint) / (beside / n_beside);
    ++rows;
  }
  ASSERT_GT(rows, 20) << "too few rows with water both on the paint and beside it";
  ASSERT_GT(n_dry_paint, 200);
  const double ratio = ratio_sum / rows;
  std::printf("water on the paint / beside it: %.3f over %d rows; dry paint %.3f\n", ratio, rows,
              dry_paint / n_dry_paint);
  EXPECT_NEAR(ratio, 1.0, 0.05) << "the paint is not under the puddle's water";
  EXPECT_NEAR(dry_paint / n_dry_paint, 0.3, 0.03) << "the dry paint does not show";
  fs::remove_all(dir);
}

// A puddle's shoreline follows the road's relief within its band: water in the low spots outside
// the smooth field's edge, dry islands inside it — and nothing of that beyond the band, where the
// mask is 0 or 1. (With a smooth edge, the band's outer half would be dry and its inner half
// water.)
TEST(PovRayGround, ShorelinesAreRaggedWithinTheirBandAndExactBeyondIt) {
  SKIP_WITHOUT_POVRAY();
  const ExportParams look = calm_puddles(640, 0.4, 1.5);
  const sim::PuddleField field(look.ground.puddles, look.ground.puddles.seed);
  const fs::path dir = still_folder("shore", look, kWaterUnderWhiteSky);
  const auto image = render_still(dir);
  ASSERT_EQ(image.size(), static_cast<std::size_t>(3 * look.width * look.height));

  // Pixels within 12 m of the camera (a pixel spans under 3 cm of ground along the line of
  // sight, so the relief's 10 cm octave is drawn), by where they lie against the band; water is
  // anything brighter than half the mirror's head-on 2 %.
  const GroundPixels pixels(look.camera, look.width, look.height, 0.0);
  struct Count {
    int wet = 0, all = 0;
    [[nodiscard]] double share() const { return static_cast<double>(wet) / std::max(all, 1); }
  };
  Count dry_side, outer_band, inner_band, water_side;
  for (std::size_t p = 0; p < pixels.width() * static_cast<std::size_t>(pixels.height()); ++p) {
    if (!pixels.hits(p) || pixels.z(p) > 8.0) continue;
    const double share = field.share(pixels.x(p), pixels.z(p));
    Count& c = share <= 0.0  ? dry_side
               : share < 0.5 ? outer_band
               : share < 1.0 ? inner_band
                             : water_side;
    c.wet += image[3 * p + 1] > 0.01 ? 1 : 0;
    ++c.all;
  }
  std::printf(
      "water: %.4f beyond the band on the dry side, %.3f in its outer half, %.3f in its "
      "inner half, %.4f beyond it in the water (%d, %d, %d, %d pixels)\n",
      dry_side.share(), outer_band.share(), inner_band.share(), water_side.share(), dry_side.all,
      outer_band.all, inner_band.all, water_side.all);
  ASSERT_GT(std::min({dry_side.all, outer_band.all, inner_band.all, water_side.all}), 2000);
  EXPECT_LT(dry_side.share(), 0.002);
  EXPECT_GT(water_side.share(), 0.998);
  EXPECT_GT(outer_band.share(), 0.1) << "no stray water outside the smooth edge";
  EXPECT_LT(outer_band.share(), 0.5);
  EXPECT_LT(inner_band.share(), 0.95) << "no dry islands inside the smooth edge";
  EXPECT_GT(inner_band.share(), 0.5);
  fs::remove_all(dir);
}

/// Puddles whose water rises and falls by 2 mm in gentle swells (slopes under 0.6 %) that cross
/// its level along lines a metre apart, over a black ground, under a sky whose brightness grows
/// with the height of the direction: the water mirrors a smoothly changing sky everywhere.
constexpr const char* kSwellsUnderLinearSky = R"(
#undef RT_PuddleHeight
#declare RT_PuddleHeight = function(x, y, z) { 0.002 * sin(3 * x) * sin(3 * z) }
#declare Dry = texture { pigment { rgb 0 } finish { ambient 0 diffuse 0 } }
plane { y, 0
  texture { RT_WetGround(Dry) }
  interior { ior 1.33 }
}
sky_sphere { pigment { gradient y color_map { [0 rgb 0] [1 rgb 10] } } }
)";

// The water's normal is a pattern normal of its height, and POV-Ray wraps a pattern's value into
// 0..1: heights a hair below the water's level read as ~1. Until 2026-12-05 the normal took the
// heights as they are, so wherever its samples straddled the level it tilted wildly, and every
// zero contour of the height field was a line of false glints and black specks. A pixel is a
// speck here if it differs by more than a quarter from both its neighbours in the row; smooth
// swells give none.
TEST(PovRayGround, TheWaterLevelIsNoEdge) {
  SKIP_WITHOUT_POVRAY();
  const ExportParams look = calm_puddles(320, 0.9, 3.0);
  const sim::PuddleField field(look.ground.puddles, look.ground.puddles.seed);
  const fs::path dir = still_folder("level", look, kSwellsUnderLinearSky);
  const auto image = render_still(dir);
  ASSERT_EQ(image.size(), static_cast<std::size_t>(3 * look.width * look.height));
  const GroundPixels pixels(look.camera, look.width, look.height, 0.0);
  int water = 0, specks = 0;
  for (int j = 0; j < look.height; ++j) {
    for (int i = 1; i + 1 < look.width; ++i) {
      const std::size_t p = static_cast<std::size_t>(j) * look.width + i;
      if (!pixels.hits(p) || pixels.z(p) > 15.0) continue;
      if (field.share(pixels.x(p), pixels.z(p)) < 1.0 ||
          field.share(pixels.x(p - 1), pixels.z(p - 1)) < 1.0 ||
          field.share(pixels.x(p + 1), pixels.z(p + 1)) < 1.0) {
        continue;
      }
      const float here = image[3 * p + 1];
      const float left = image[3 * (p - 1) + 1], right = image[3 * (p + 1) + 1];
      const auto apart = [here](float other) {
        return std::abs(here - other) > 0.25f * std::max(here, other);
      };
      ++water;
      specks += apart(left) && apart(right) ? 1 : 0;
    }
  }
  std::printf("%d specks in %d pixels of water\n", specks, water);
  ASSERT_GT(water, 5000);
  EXPECT_EQ(specks, 0) << "the water's normal breaks where its height crosses 0";
  fs::remove_all(dir);
}

TEST(PovRayGround, SplashesGoOnPastTheSimulatedVolumeWithoutAnEdge) {
  SKIP_WITHOUT_POVRAY();
  // Heavy rain simulated to far_m = 6 m only, the camera looking down the street; the rain mask
  // of the splashes alone (the falling drops taken out) in 8 frames, a still exposure so that
  // more droplets are kept. The splash light per image row, against the distance of the ground
  // that row sees, is continuous across far_m: the rows just beyond see about as much splash
  // as the rows just before.
  sim::SimParams sim;
  sim.camera.look_at = {0.0, 1.0, 0.0};
  sim.camera.aspect = 640.0 / 360.0;
  sim.camera.width_px = 640;
  sim.camera.exposure_s = 0.0;
  sim.rain.rate_mm_per_h = 30.0;
  sim.rain.far_m = 6.0;
  sim.ripples.enabled = false;
  sim::World world(sim);
  std::vector<sim::Frame> frames;
  for (int n = 1; n <= 8; ++n) {
    world.advance_to(0.5 + n / 24.0);
    frames.push_back(world.snapshot(n));
    frames.back().drops = sim::Drops{};
  }
  ExportParams look;
  look.camera = sim.camera;
  look.mask = true;
  look.min_streak_coverage = 0.0;
  look.splash_keep = 1.0;
  const fs::path dir = wet_folder("edge", look, frames);
  std::vector<float> px;
  for (int n = 1; n <= 8; ++n) {
    const std::string name = frame_file_name("mask", n, 4, ".pov");
    write_file_atomic(dir / "frames" / name,
                      mask_text("frames/" + frame_file_name("frame", n, 4, ".pov")));
  }
  ASSERT_EQ(run_povray(dir, "mask.ini +SF1 +EF8"), 0) << log_of(dir);
  for (int n = 1; n <= 8; ++n) {
    const auto one = read_rgb(dir / "images" / frame_file_name("mask", n, 4, ".png"));
    ASSERT_FALSE(one.empty());
    px.resize(one.size(), 0.0f);
    for (std::size_t i = 0; i < one.size(); ++i) px[i] += one[i];
  }
  // The volume's footprint ends fb1 ahead of the eye along the view (+z here). Each image row
  // sees the ground at one distance: the splash light of the 16 rows just short of that edge
  // and of the 16 just past it. Light per pixel grows gently with distance (a pixel sees more
  // ground, at a slant); an edge would drop it to nothing.
  const double edge_z = world.region().origin().z + world.region().fb1();
  const GroundPixels pixels(look.camera, look.width, look.height, 0.0);
  std::vector<double> light(static_cast<std::size_t>(look.height), 0.0);
  int edge_row = -1;
  for (int j = 0; j < look.height; ++j) {
    const std::size_t mid = static_cast<std::size_t>(j) * look.width + look.width / 2;
    if (!pixels.hits(mid)) continue;
    if (edge_row < 0 && pixels.z(mid) < edge_z) edge_row = j;  // rows run from far to near
    for (int i = 0; i < look.width; ++i) {
      light[static_cast<std::size_t>(j)] += px[3 * (static_cast<std::size_t>(j) * look.width + i)];
    }
  }
  ASSERT_GT(edge_row, 16);
  ASSERT_LT(edge_row + 16, look.height);
  double before = 0.0, beyond = 0.0;
  for (int k = 0; k < 16; ++k) {
    before += light[static_cast<std::size_t>(edge_row + k)];
    beyond += light[static_cast<std::size_t>(edge_row - 1 - k)];
  }
  ASSERT_GT(before, 0.0);
  EXPECT_GT(beyond / before, 0.7) << "before " << before << ", beyond " << beyond;
  EXPECT_LT(beyond / before, 1.6) << "before " << before << ", beyond " << beyond;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace raintrace::povgen
