// Frame → values: frustum culling, the near/far split, streak geometry and opacity.
#include "povgen/frame_values.h"

#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <vector>

#include "povgen/drop_shape.h"
#include "povgen/test_support/atlas_texels.h"
#include "povgen/test_support/synthetic_rain.h"
#include "povgen/view_frustum.h"

namespace raintrace::povgen {
namespace {

/// Default look: camera at (0, 1.6, −5) looking along +z, 60° horizontal, 640×360.
ExportParams default_look() { return ExportParams{}; }

void add_drop(sim::Frame& frame, glm::vec3 position, glm::vec3 velocity, float diameter) {
  sim::Drops& d = frame.drops;
  d.id.push_back(d.id.size());
  d.position.push_back(position);
  d.velocity.push_back(velocity);
  d.acceleration.push_back(glm::vec3{0.0f});
  d.diameter.push_back(diameter);
  d.age.push_back(0.0f);
  d.vanishing_rate.push_back(0.0f);
  d.opacity.push_back(1.0f);
  d.colour.push_back(glm::vec3{1.0f});
}

/// A 4 mm drop 1 m in front of the default eye, falling at 8.8 m/s.
sim::Frame big_drop_one_metre_away() {
  sim::Frame frame;
  add_drop(frame, {0.0f, 1.6f, -4.0f}, {0.0f, -8.8f, 0.0f}, 4e-3f);
  return frame;
}

/// The default look at 1920×1080 (a pixel 0.6 mm at 1 m), every streak kept at its own opacity.
ExportParams full_hd_look_keeping_every_streak() {
  ExportParams look = default_look();
  look.width = 1920;
  look.height = 1080;
  look.min_streak_coverage = 0.0;
  return look;
}

TEST(ViewFrustum, CullsAtTheEdgeOfTheFieldOfView) {
  // At depth 5 (z = 0) the half width is 5·tan 30° = 2.88675 m, the half height 2.88675/(16/9)
  // = 1.62380 m around y = 1.6.
  const ViewFrustum view(sim::Camera{}, 16.0 / 9.0);
  EXPECT_TRUE(view.sphere_visible({2.85f, 1.6f, 0.0f}, 0.001f));
  EXPECT_FALSE(view.sphere_visible({2.95f, 1.6f, 0.0f}, 0.001f));
  EXPECT_TRUE(view.sphere_visible({-2.85f, 1.6f, 0.0f}, 0.001f));
  EXPECT_FALSE(view.sphere_visible({-2.95f, 1.6f, 0.0f}, 0.001f));
  EXPECT_TRUE(view.sphere_visible({0.0f, 1.6f + 1.60f, 0.0f}, 0.001f));
  EXPECT_FALSE(view.sphere_visible({0.0f, 1.6f + 1.65f, 0.0f}, 0.001f));
  EXPECT_FALSE(view.sphere_visible({0.0f, 1.6f - 1.65f, 0.0f}, 0.001f));
  // Behind the camera.
  EXPECT_FALSE(view.sphere_visible({0.0f, 1.6f, -6.0f}, 0.001f));
  // A big sphere just outside still reaches into view.
  EXPECT_TRUE(view.sphere_visible({2.95f, 1.6f, 0.0f}, 0.2f));
}

TEST(FrameValues, DropsOutsideTheViewAreNotWritten) {
  sim::Frame frame;
  add_drop(frame, {0.0f, 1.6f, 5.0f}, {0.0f, -9.0f, 0.0f}, 2e-3f);    // in view, far
  add_drop(frame, {30.0f, 1.6f, 5.0f}, {0.0f, -9.0f, 0.0f}, 2e-3f);   // far right
  add_drop(frame, {0.0f, 1.6f, -8.0f}, {0.0f, -9.0f, 0.0f}, 2e-3f);   // behind
  add_drop(frame, {0.0f, 20.0f, 5.0f}, {0.0f, -9.0f, 0.0f}, 2e-3f);   // above
  add_drop(frame, {0.1f, 1.5f, -3.0f}, {0.0f, -9.0f, 0.0f}, 2e-3f);   // in view, near
  add_drop(frame, {-2.0f, 1.6f, -3.5f}, {0.0f, -9.0f, 0.0f}, 2e-3f);  // near, left of view
  // 8192 px wide: a pixel at depth 2 m is 2·2·tan30°/8192 = 0.28 mm, so the 2 mm drop is a sphere.
  ExportParams look = default_look();
  look.width = 8192;
  look.height = 4608;
  look.min_streak_coverage = 0.0;
  look.camera.exposure_s = 0.0;  // sharp: near drops stay drops
  const FrameValues values = build_frame_values(frame, look);
  EXPECT_EQ(values.streaks.size(), 1u);
  ASSERT_EQ(values.drops.size(), 1u);
  EXPECT_FLOAT_EQ(values.drops[0].centre.x, 0.1f);
}

TEST(FrameValues, NearFarSplitFollowsSphereDistance) {
  // Distances from the eye (0, 1.6, −5): 2.9 m and 3.1 m along the view axis. 5 mm drops: a
  // pixel at 2.9 m is 2·2.9·tan30°/640 = 5.2 mm, so 6 mm drops are wider than a pixel.
  sim::Frame frame;
  add_drop(frame, {0.0f, 1.6f, -2.1f}, {0.0f, -9.0f, 0.0f}, 6e-3f);
  add_drop(frame, {0.0f, 1.6f, -1.9f}, {0.0f, -9.0f, 0.0f}, 6e-3f);
  ExportParams look = default_look();
  look.sphere_distance_m = 3.0;
  look.min_streak_coverage = 0.0;
  look.camera.exposure_s = 0.0;
  FrameValues values = build_frame_values(frame, look);
  EXPECT_EQ(values.drops.size(), 1u);
  EXPECT_EQ(values.streaks.size(), 1u);
  look.sphere_distance_m = 0.0;  // everything streaks
  values = build_frame_values(frame, look);
  EXPECT_EQ(values.drops.size(), 0u);
  EXPECT_EQ(values.streaks.size(), 2u);
}

TEST(FrameValues, LargeNearDropsAreFlattenedAtEqualVolume) {
  sim::Frame frame;
  add_drop(frame, {0.0f, 1.6f, -4.0f}, {0.0f, -9.0f, 0.0f}, 5e-3f);
  add_drop(frame, {0.1f, 1.6f, -4.0f}, {0.0f, -2.0f, 0.0f}, 0.5e-3f);
  ExportParams look = default_look();  // a pixel at 1 m: 2·tan30°/8192 = 0.14 mm
  look.width = 8192;
  look.height = 4608;
  look.camera.exposure_s = 0.0;
  const FrameValues values = build_frame_values(frame, look);
  ASSERT_EQ(values.drops.size(), 2u);
  const SphereValue& big = values.drops[0];
  // Beard-Chuang at 5 mm: 0.7060875. Equal volume: a²·b = R³ with b = ratio·a.
  EXPECT_NEAR(big.axis_ratio, 0.7060875, 1e-6);
  const double a = big.radius;
  EXPECT_NEAR(a * a * a * big.axis_ratio, 2.5e-3 * 2.5e-3 * 2.5e-3, 1e-12);
  // 0.5 mm drops are round to 0.1 % and written as bare spheres.
  EXPECT_EQ(values.drops[1].axis_ratio, 1.0f);
}

TEST(FrameValues, NearDropsShowTheirMotionDuringTheExposure) {
  // A 4 mm drop 1 m from the eye at 1920 px (a pixel 0.6 mm): Beard-Chuang axis ratio 0.77932,
  // 2a = 4.34666 mm, height 2b = 3.38742 mm.
  const sim::Frame frame = big_drop_one_metre_away();
  ExportParams look = full_hd_look_keeping_every_streak();
  // exposure_s = 0: the drop as it is, a sharp refractive sphere.
  look.camera.exposure_s = 0.0;
  FrameValues values = build_frame_values(frame, look);
  ASSERT_EQ(values.drops.size(), 1u);
  EXPECT_NEAR(values.drops[0].axis_ratio, 0.77932, 1e-4);
  EXPECT_FLOAT_EQ(values.drops[0].centre.y, 1.6f);
  // 0.2 ms: it moves 1.76 mm, half its height — swept over its path: centred half-way down,
  // stretched to (3.38742 + 1.76)/3.38742 of its height.
  look.camera.exposure_s = 0.0002;
  values = build_frame_values(frame, look);
  ASSERT_EQ(values.drops.size(), 1u);
  EXPECT_NEAR(values.drops[0].centre.y, 1.6f - 0.00088f, 1e-6);
  EXPECT_NEAR(values.drops[0].axis_ratio, 0.77932 * (1.0 + 1.76 / 3.38742), 1e-4);
  // 20 ms: 17.6 cm, 51 heights: a streak that long, no sphere.
  look.camera.exposure_s = 0.02;
  values = build_frame_values(frame, look);
  EXPECT_TRUE(values.drops.empty());
  ASSERT_EQ(values.streaks.size(), 1u);
  const auto& c = values.streaks[0].corners;
  EXPECT_NEAR(glm::length(c[3] - c[0]), 0.176 + 0.00338742, 1e-5);
  // Wider than a pixel: the resolved columns, drawn the drop's own width.
  const StreakAtlasLayout atlas;
  EXPECT_LT(values.streaks[0].cell % atlas.columns(), atlas.motions);
  EXPECT_NEAR(glm::length(c[1] - c[0]), 0.00434666, 1e-6);
}

TEST(FrameValues, SubPixelNearDropsBecomeStreaks) {
  // 1 mm drop 2 m away at 640 px: a pixel is 2·2·tan30°/640 = 3.6 mm, the drop far smaller.
  sim::Frame frame;
  add_drop(frame, {0.0f, 1.6f, -3.0f}, {0.0f, -9.0f, 0.0f}, 1e-3f);
  ExportParams look = default_look();
  look.min_streak_coverage = 0.0;  // its coverage 1/3.6 is below the default 1
  const FrameValues values = build_frame_values(frame, look);
  EXPECT_TRUE(values.drops.empty());
  EXPECT_EQ(values.streaks.size(), 1u);
}

/// The coverage a streak quad carries, ∫α dA over the quad as POV-Ray draws it: the quad's area
/// times its atlas cell's mean opacity (the trapezoid rule over the texels, which bilinear
/// filtering between corner-texel centres amounts to).
double carried_coverage(const StreakValue& streak) {
  static const StreakAtlasLayout atlas;
  static const std::vector<std::uint16_t> px = streak_atlas_pixels(atlas);
  const double mean = test_support::atlas_cell_mean(px, atlas, streak.cell / atlas.columns(),
                                                    streak.cell % atlas.columns());
  const auto& c = streak.corners;
  return mean * glm::length(c[3] - c[0]) * glm::length(c[1] - c[0]);
}

TEST(FrameValues, OutOfFocusRainIsWidenedByItsBlurDiscAndKeepsItsLight) {
  // A 2 mm drop (2.05074 mm across, 1.90225 mm along) falling at 9 m/s, 2 m from the eye, a
  // lens 20 mm open focused 20 m away (look_at): a thin lens blurs it over a disc
  // 0.02·|2 − 20|/20 = 18 mm across at its own depth, five pixels there (3.608 mm each).
  sim::Frame frame;
  add_drop(frame, {0.0f, 1.6f, -3.0f}, {0.0f, -9.0f, 0.0f}, 2e-3f);
  ExportParams look = default_look();
  look.min_streak_coverage = 0.0;
  look.camera.look_at = {0.0, 1.6, 15.0};
  const FrameValues sharp = build_frame_values(frame, look);
  look.aperture_m = 0.02;
  look.focal_blur = FocalBlur::rain;
  const FrameValues blurred = build_frame_values(frame, look);
  ASSERT_EQ(sharp.streaks.size(), 1u);
  ASSERT_EQ(blurred.streaks.size(), 1u);
  const auto& c = blurred.streaks[0].corners;
  // The outline widened by the disc: 18 mm more across and along.
  EXPECT_NEAR(glm::length(c[1] - c[0]), 0.00205074 + 0.018, 1e-6);
  EXPECT_NEAR(glm::length(c[3] - c[0]), 0.18 + 0.00190225 + 0.018, 1e-5);
  // Wider than a pixel now: the resolved columns (the sharp drop is sub-pixel).
  const StreakAtlasLayout atlas;
  EXPECT_GE(sharp.streaks[0].cell % atlas.columns(), atlas.motions);
  EXPECT_LT(blurred.streaks[0].cell % atlas.columns(), atlas.motions);
  // Defocus spreads the drop's light, it adds none: both carry the drop's area, π/4·2a·2b,
  // to the atlas rows' 4.4 % and the texel sampling's few %.
  const double area = std::numbers::pi / 4 * 0.00205074 * 0.00190225;
  EXPECT_NEAR(carried_coverage(sharp.streaks[0]) / area, 1.0, 0.06);
  EXPECT_NEAR(carried_coverage(blurred.streaks[0]) / area, 1.0, 0.06);
}

TEST(FrameValues, RainInTheFocalPlaneOrTracedBlurIsDrawnSharp) {
  sim::Frame frame;
  add_drop(frame, {0.3f, 1.5f, 15.0f}, {0.5f, -9.0f, 0.0f}, 2e-3f);  // 20 m deep
  add_drop(frame, {0.0f, 1.6f, -3.0f}, {0.0f, -9.0f, 0.0f}, 2e-3f);  // 2 m deep
  ExportParams look = default_look();
  look.min_streak_coverage = 0.0;
  look.camera.look_at = {0.0, 1.6, 15.0};
  const FrameValues pinhole = build_frame_values(frame, look);
  look.aperture_m = 0.02;
  look.focal_blur = FocalBlur::rain;
  const FrameValues rain = build_frame_values(frame, look);
  look.focal_blur = FocalBlur::traced;  // POV-Ray blurs the quads itself
  const FrameValues traced = build_frame_values(frame, look);
  ASSERT_EQ(pinhole.streaks.size(), 2u);
  ASSERT_EQ(rain.streaks.size(), 2u);
  ASSERT_EQ(traced.streaks.size(), 2u);
  EXPECT_EQ(rain.streaks[0].corners, pinhole.streaks[0].corners);  // in focus
  EXPECT_EQ(rain.streaks[0].cell, pinhole.streaks[0].cell);
  EXPECT_NE(rain.streaks[1].corners, pinhole.streaks[1].corners);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(traced.streaks[i].corners, pinhole.streaks[i].corners) << i;
    EXPECT_EQ(traced.streaks[i].cell, pinhole.streaks[i].cell) << i;
  }
}

TEST(FrameValues, ANearDropOutOfFocusIsTheLenssDiscNotASphere) {
  // A still 4 mm drop 1 m away at 1920 px (a pixel 0.6 mm) is a refractive sphere. Focused
  // 20 m away with a 20 mm opening, its blur disc is 0.02·19/20 = 19 mm, 32 pixels: POV-Ray's
  // sharp sphere would be wrong, so it is drawn as its blurred streak. Traced blur keeps the
  // sphere (POV-Ray blurs it).
  const sim::Frame frame = big_drop_one_metre_away();
  ExportParams look = full_hd_look_keeping_every_streak();
  look.camera.exposure_s = 0.0;
  look.camera.look_at = {0.0, 1.6, 15.0};
  look.aperture_m = 0.02;
  look.focal_blur = FocalBlur::traced;
  EXPECT_EQ(build_frame_values(frame, look).drops.size(), 1u);
  look.focal_blur = FocalBlur::rain;
  const FrameValues values = build_frame_values(frame, look);
  EXPECT_TRUE(values.drops.empty());
  ASSERT_EQ(values.streaks.size(), 1u);
  EXPECT_NEAR(glm::length(values.streaks[0].corners[1] - values.streaks[0].corners[0]),
              0.00434666 + 0.019, 1e-5);
}

TEST(FrameValues, StreakLengthFollowsExposureAndFacesTheCamera) {
  // A 2 mm drop falling at 9 m/s, 10 m in front of the eye, exposure 0.02 s. Beard-Chuang
  // flattens it to axis ratio 0.92759: 2a = 2 mm / 0.92759^(1/3) = 2.05074 mm across and
  // 2b = 1.90225 mm along. L = 9·0.02 + 2b = 0.181902 m. One pixel at depth 10 m is
  // 2·10·tan30°/640 = 18.0422 mm, wider than the drop, so the quad is one pixel wide.
  sim::Frame frame;
  add_drop(frame, {0.0f, 1.6f, 5.0f}, {0.0f, -9.0f, 0.0f}, 2e-3f);
  ExportParams look = default_look();
  look.min_streak_coverage = 0.0;  // every streak, at its own opacity
  const FrameValues values = build_frame_values(frame, look);
  ASSERT_EQ(values.streaks.size(), 1u);
  const auto& c = values.streaks[0].corners;
  const glm::vec3 along = c[3] - c[0];
  const glm::vec3 across = c[1] - c[0];
  EXPECT_NEAR(glm::length(along), 0.181902, 1e-5);
  EXPECT_NEAR(glm::length(across), 0.0180422, 1e-5);
  // Along the fall (−y), starting b above the drop; across ⟂ both the fall and the view (x).
  EXPECT_NEAR(c[0].y + c[1].y, 2.0f * (1.6f + 0.000951f), 1e-5);
  EXPECT_NEAR(glm::dot(glm::normalize(along), glm::vec3{0, -1, 0}), 1.0, 1e-6);
  EXPECT_NEAR(std::fabs(glm::normalize(across).x), 1.0, 1e-6);
  // Opacity (Garg & Nayar): each point is covered 2b / travel = 1.90225/180 = 0.0105681 of the
  // exposure, and the drop fills 2.05074/18.0422 = 0.113664 of the pixel: 0.00120121. It moves
  // 94.6 of its sizes (column 7, the longest) and is narrower than a pixel (the sub-pixel
  // columns, + 8); the row is the nearest 2^(−r/8) to that coverage times the column's gain.
  const StreakAtlasLayout atlas;
  const int column = 7 + atlas.motions;
  const auto row = static_cast<int>(
      std::lround(-8.0 * std::log2(0.00120121 * streak_atlas_column_gain(atlas, column))));
  EXPECT_EQ(values.streaks[0].cell, row * atlas.columns() + column);
}

TEST(FrameValues, TheStreaksLightDoesNotDependOnTheExposure) {
  // The quad's area times its middle opacity is the drop's coverage of the picture: the same
  // at 0.01 and 0.04 s (the length grows as the opacity falls), up to the atlas rows' 4.4 %.
  sim::Frame frame;
  add_drop(frame, {0.0f, 1.6f, 5.0f}, {0.0f, -9.0f, 0.0f}, 2e-3f);
  ExportParams look = default_look();
  look.min_streak_coverage = 0.0;
  const StreakAtlasLayout atlas;
  auto light = [&](double exposure) {
    look.camera.exposure_s = exposure;
    const FrameValues v = build_frame_values(frame, look);
    EXPECT_EQ(v.streaks.size(), 1u);
    const auto& c = v.streaks[0].corners;
    const double area = glm::length(c[3] - c[0]) * glm::length(c[1] - c[0]);
    return area * atlas.row_opacity(v.streaks[0].cell / atlas.columns());
  };
  const double short_exposure = light(0.01);
  const double long_exposure = light(0.04);
  EXPECT_NEAR(long_exposure / short_exposure, 1.0, 0.09);
}

TEST(FrameValues, SlantedStreaksFollowTheVelocity) {
  // Wind-blown drop: velocity (3, −8, 0) at depth 8 m to the right of the axis.
  sim::Frame frame;
  const glm::vec3 v{3.0f, -8.0f, 0.0f};
  add_drop(frame, {1.0f, 1.6f, 3.0f}, v, 3e-3f);
  ExportParams look = default_look();
  look.min_streak_coverage = 0.0;  // 3 mm over a 14 mm pixel: fainter than the default
  const FrameValues values = build_frame_values(frame, look);
  ASSERT_EQ(values.streaks.size(), 1u);
  const auto& c = values.streaks[0].corners;
  const glm::vec3 along = glm::normalize(c[3] - c[0]);
  EXPECT_NEAR(glm::dot(along, glm::normalize(v)), 1.0, 1e-5);
  // Length: |v|·t + 2b = 8.5440·0.02 + 2.7043 mm = 0.173584 m (3 mm: axis ratio 0.85582,
  // 2a = 3.1598 mm, 2b = 2.7043 mm).
  EXPECT_NEAR(glm::length(c[3] - c[0]), 0.173584, 2e-5);
  // The side is perpendicular to the motion and to the line of sight (camera-facing).
  const glm::vec3 side = glm::normalize(c[1] - c[0]);
  const glm::vec3 middle = 0.25f * (c[0] + c[1] + c[2] + c[3]);
  const glm::vec3 sight = glm::normalize(glm::vec3{0.0f, 1.6f, -5.0f} - middle);
  EXPECT_NEAR(glm::dot(side, along), 0.0, 1e-5);
  EXPECT_NEAR(glm::dot(side, sight), 0.0, 1e-5);
}

TEST(FrameValues, VanishedDropsAreSkipped) {
  sim::Frame frame;
  add_drop(frame, {0.0f, 1.6f, 5.0f}, {0.0f, -9.0f, 0.0f}, 2e-3f);
  frame.drops.opacity[0] = 0.0f;
  EXPECT_TRUE(build_frame_values(frame, default_look()).streaks.empty());
}

/// 4000 drops of 1 mm at depth 10 m, spread across the view (ids 0..3999).
sim::Frame faint_rain() {
  sim::Frame frame;
  for (int i = 0; i < 4000; ++i) {
    const float x = -2.0f + 4.0f * static_cast<float>(i % 200) / 200.0f;
    const float y = 0.8f + 1.6f * static_cast<float>(i / 200) / 20.0f;
    add_drop(frame, {x, y, 5.0f}, {0.0f, -9.0f, 0.0f}, 1e-3f);
  }
  return frame;
}

TEST(FrameValues, FaintStreaksAreThinnedButKeepTheirExpectedLight) {
  // A 1 mm drop (2a = 1.00587 mm, 2b = 0.98837 mm) at 9 m/s, 10 m away: covered 0.98837/180 of
  // the exposure over 1.00587/18.0422 of a pixel's width: 3.0612e-4. Under
  // min_streak_coverage 0.01 each survives with probability 0.030612 and is drawn at 0.01:
  // 4000 · 0.030612 = 122 expected, binomial σ ≈ 11.
  const sim::Frame frame = faint_rain();
  ExportParams look = default_look();
  look.min_streak_coverage = 0.01;
  const FrameValues thinned = build_frame_values(frame, look);
  EXPECT_NEAR(static_cast<double>(thinned.streaks.size()), 122.0, 40.0);
  const StreakAtlasLayout atlas;
  const double gain = streak_atlas_column_gain(atlas, atlas.columns() - 1);
  auto row_of = [&](double coverage) {
    return static_cast<int>(std::lround(-8.0 * std::log2(coverage * gain)));
  };
  for (const StreakValue& s : thinned.streaks) EXPECT_EQ(s.cell / atlas.columns(), row_of(0.01));
  // 0 keeps every streak at its own opacity.
  look.min_streak_coverage = 0.0;
  const FrameValues all = build_frame_values(frame, look);
  ASSERT_EQ(all.streaks.size(), 4000u);
  EXPECT_EQ(all.streaks[0].cell / atlas.columns(), row_of(3.0612e-4));
  // Fainter than the atlas can draw (its faintest row, 2^−13, over the smallest column gain):
  // thinned to that, never dropped outright. A 20 m/s drop is covered half as long, 1.53e-4.
  sim::Frame fast = faint_rain();
  for (glm::vec3& v : fast.drops.velocity) v.y = -18.0f;
  const FrameValues floor = build_frame_values(fast, look);
  const double survival = 1.5306e-4 / streak_atlas_faintest_coverage(atlas);
  ASSERT_LT(survival, 1.0);
  EXPECT_NEAR(static_cast<double>(floor.streaks.size()), 4000.0 * survival, 130.0);
  for (const StreakValue& s : floor.streaks) {
    EXPECT_EQ(s.cell / atlas.columns(), row_of(streak_atlas_faintest_coverage(atlas)));
  }
}

TEST(FrameValues, UnsetLevelOfDetailIsCoarserAtPreviewThanAtFinal) {
  ExportParams look = default_look();
  ASSERT_LT(look.min_streak_coverage, 0.0);  // not set
  look.quality = Quality::preview;
  EXPECT_EQ(streak_coverage_threshold(look), kPreviewStreakCoverage);
  look.quality = Quality::final;
  EXPECT_EQ(streak_coverage_threshold(look), kFinalStreakCoverage);
  EXPECT_LT(kFinalStreakCoverage, kPreviewStreakCoverage);
  look.min_streak_coverage = 0.0;  // set: whatever the quality
  EXPECT_EQ(streak_coverage_threshold(look), 0.0);
  // The 4000 faint streaks: a preview keeps about a third as many as a final render.
  look.min_streak_coverage = -1.0;
  look.quality = Quality::preview;
  const std::size_t preview = build_frame_values(faint_rain(), look).streaks.size();
  look.quality = Quality::final;
  const std::size_t final_count = build_frame_values(faint_rain(), look).streaks.size();
  EXPECT_NEAR(static_cast<double>(preview) / static_cast<double>(final_count), 0.3, 0.1);
}

TEST(FrameValues, ThinningKeepsTheSameDropsFromFrameToFrame) {
  // The drops fall 5 cm between frames: coverage hardly changes, so the survivors must be the
  // same drops (no flicker), whatever their order in the frame.
  sim::Frame first = faint_rain();
  sim::Frame second = faint_rain();
  for (glm::vec3& p : second.drops.position) p.y -= 0.05f;
  std::reverse(second.drops.id.begin(), second.drops.id.end());
  std::reverse(second.drops.position.begin(), second.drops.position.end());
  ExportParams look = default_look();
  look.min_streak_coverage = 0.01;
  const FrameValues a = build_frame_values(first, look);
  const FrameValues b = build_frame_values(second, look);
  ASSERT_EQ(a.streaks.size(), b.streaks.size());
  ASSERT_FALSE(a.streaks.empty());
  // b lists the same drops in reverse: its last streak is a's first, moved down 5 cm.
  EXPECT_NEAR(b.streaks.back().corners[0].y, a.streaks.front().corners[0].y - 0.05f, 1e-5f);
  EXPECT_NEAR(b.streaks.back().corners[0].x, a.streaks.front().corners[0].x, 1e-5f);
}

/// 4000 splash droplets 1 mm across in front of the camera (depth 5 m, where a 640 px pixel is
/// 9.02 mm), thrown sideways and up at speeds that differ from droplet to droplet, each with
/// opacity `weight` (a level-of-detail weight above 1 stands for several droplets).
sim::Frame splashing(float fall_s = 0.0f, float weight = 1.0f) {
  sim::Frame frame;
  std::uint32_t state = 12345;
  auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) * 0x1.0p-24f;
  };
  sim::Drops& d = frame.splashes;
  for (int i = 0; i < 4000; ++i) {
    glm::vec3 v{next() - 0.5f, 1.0f + next(), next() - 0.5f};
    glm::vec3 p{-2.0f + 4.0f * next(), 0.5f + next(), 0.0f};
    // Later in the flight: gravity has only changed the vertical speed.
    p += fall_s * v;
    v.y -= 9.81f * fall_s;
    d.id.push_back(0x9e3779b97f4a7c15ULL * (i + 1));
    d.position.push_back(p);
    d.velocity.push_back(v);
    d.acceleration.push_back({0.0f, -9.81f, 0.0f});
    d.diameter.push_back(1e-3f);
    d.opacity.push_back(weight);
  }
  return frame;
}

TEST(FrameValues, SplashDropletsAreDrawnLikeDrops) {
  // Every droplet keeps its light: no coverage thinning, splash_keep 1. At depth 5 m a 1 mm
  // droplet is thinner than a pixel, so each one is a streak, like a far drop.
  ExportParams look = default_look();
  look.splash_keep = 1.0;
  look.min_streak_coverage = 0.0;
  const FrameValues values = build_frame_values(splashing(), look);
  EXPECT_EQ(values.drops.size(), 0u);
  EXPECT_EQ(values.streaks.size(), 4000u);
}

TEST(FrameValues, SplashDropletWeightMakesItsStreakMoreOpaque) {
  // The same droplets carrying weight 4 (each stands for 4): their streaks are 4 times as
  // opaque, i.e. two halvings up the atlas (row r has opacity 2^(-r / kStreakRowsPerHalving)),
  // until opacity 1.
  ExportParams look = default_look();
  look.splash_keep = 1.0;
  look.min_streak_coverage = 0.0;
  const StreakAtlasLayout atlas;
  const FrameValues one = build_frame_values(splashing(0.0f, 1.0f), look, atlas);
  const FrameValues four = build_frame_values(splashing(0.0f, 4.0f), look, atlas);
  ASSERT_EQ(one.streaks.size(), four.streaks.size());
  std::size_t compared = 0;
  for (std::size_t i = 0; i < one.streaks.size(); ++i) {
    const int row = one.streaks[i].cell / atlas.columns();
    if (row < 2 * kStreakRowsPerHalving) continue;
    EXPECT_EQ(four.streaks[i].cell / atlas.columns(), row - 2 * kStreakRowsPerHalving);
    EXPECT_EQ(four.streaks[i].cell % atlas.columns(), one.streaks[i].cell % atlas.columns());
    ++compared;
  }
  EXPECT_GT(compared, 3000u);
}

TEST(FrameValues, SplashKeepThinsDropletsByIdAndKeepsThemThroughTheirFlight) {
  ExportParams look = default_look();
  look.min_streak_coverage = 0.0;
  look.splash_keep = 0.25;
  const FrameValues before = build_frame_values(splashing(), look);
  // Binomial(4000, 0.25): 1000 expected, σ ≈ 27.
  EXPECT_NEAR(static_cast<double>(before.streaks.size()), 1000.0, 110.0);
  // 0.1 s later every droplet has moved: the same ones survive (their ids decide).
  const FrameValues after = build_frame_values(splashing(0.1f), look);
  EXPECT_EQ(before.streaks.size(), after.streaks.size());
}

TEST(FrameValues, LightningLightSitsAtTheTopOfTheBrightestBolt) {
  sim::Frame frame;
  frame.flash = 0.8f;
  sim::Bolt bolt;
  bolt.brightness = 0.8f;
  bolt.segments.push_back({{10.0f, 300.0f, 200.0f}, {12.0f, 150.0f, 200.0f}, 0.6f, 0});
  bolt.segments.push_back({{12.0f, 150.0f, 200.0f}, {11.0f, 0.0f, 200.0f}, 0.6f, 0});
  frame.bolts.push_back(bolt);
  const FrameValues values = build_frame_values(frame, default_look());
  EXPECT_FLOAT_EQ(values.flash, 0.8f);
  EXPECT_EQ(values.flash_position, glm::vec3(10.0f, 300.0f, 200.0f));
  ASSERT_EQ(values.bolts.size(), 1u);
  // The upper segment is above the view (y 150..300 at depth 205 m, half height ≈ 66.6 m):
  // culled; the lower one crosses the view and stays.
  EXPECT_EQ(values.bolts[0].segments.size(), 1u);
}

TEST(FrameValues, BoltBranchesFaintestLastAndNoThinnerThanHalfAPixel) {
  sim::Frame frame;
  sim::Bolt bolt;
  bolt.brightness = 0.8f;         // every return stroke so far
  bolt.branch_brightness = 0.5f;  // the first alone
  bolt.segments.push_back({{0.0f, 60.0f, 400.0f}, {1.0f, 0.0f, 400.0f}, 0.6f, 0});
  bolt.segments.push_back({{0.0f, 50.0f, 400.0f}, {8.0f, 40.0f, 400.0f}, 0.3f, 1});
  bolt.segments.push_back({{8.0f, 40.0f, 400.0f}, {12.0f, 35.0f, 400.0f}, 0.15f, 2});
  frame.bolts.push_back(bolt);
  const ExportParams look = default_look();
  const FrameValues values = build_frame_values(frame, look);
  ASSERT_EQ(values.bolts.size(), 3u);  // one group per generation
  EXPECT_FLOAT_EQ(values.bolts[0].brightness, 0.8f);
  EXPECT_FLOAT_EQ(values.bolts[1].brightness, 0.5f * 0.35f);
  EXPECT_FLOAT_EQ(values.bolts[2].brightness, 0.5f * 0.35f * 0.5f);
  // 405 m from the camera a pixel is ~0.7 m across (60°, 640 px): every channel is drawn at
  // least half that in radius, its true radius kept for the glow.
  const float pixel = 2.0f * 405.0f * std::tan(30.0f * 3.14159265f / 180.0f) / 640.0f;
  for (const BoltValue& group : values.bolts) {
    ASSERT_EQ(group.segments.size(), 1u);
    const CylinderValue& c = group.segments[0];
    EXPECT_GE(c.core_radius, c.radius);
    EXPECT_GE(c.core_radius, 0.45f * pixel);
    EXPECT_LE(c.core_radius, std::max(c.radius, 0.55f * pixel));
  }
  EXPECT_FLOAT_EQ(values.bolts[0].segments[0].radius, 0.6f);
}

TEST(FrameValues, EveryGroupOfABoltKnowsItsTrunksRadius) {
  // frame_text sets the channel's light per metre by the trunk's radius, branches included.
  sim::Frame frame;
  sim::Bolt bolt;
  bolt.brightness = 0.8f;
  bolt.branch_brightness = 0.5f;
  bolt.segments.push_back({{0.0f, 60.0f, 400.0f}, {1.0f, 0.0f, 400.0f}, 0.3f, 0});
  bolt.segments.push_back({{0.0f, 50.0f, 400.0f}, {8.0f, 40.0f, 400.0f}, 0.15f, 1});
  frame.bolts.push_back(bolt);
  const FrameValues values = build_frame_values(frame, default_look());
  ASSERT_EQ(values.bolts.size(), 2u);
  EXPECT_FLOAT_EQ(values.bolts[0].trunk_radius, 0.3f);
  EXPECT_FLOAT_EQ(values.bolts[1].trunk_radius, 0.3f);
}

/// Number of places where a and b differ (sizes, then every field of every element).
std::size_t differences(const FrameValues& a, const FrameValues& b) {
  std::size_t n = (a.drops.size() != b.drops.size()) + (a.streaks.size() != b.streaks.size());
  for (std::size_t i = 0; i < std::min(a.drops.size(), b.drops.size()); ++i) {
    n += a.drops[i].centre != b.drops[i].centre || a.drops[i].radius != b.drops[i].radius ||
         a.drops[i].axis_ratio != b.drops[i].axis_ratio;
  }
  for (std::size_t i = 0; i < std::min(a.streaks.size(), b.streaks.size()); ++i) {
    n += a.streaks[i].corners != b.streaks[i].corners || a.streaks[i].cell != b.streaks[i].cell;
  }
  return n;
}

TEST(FrameValues, SameFrameGivesIdenticalValuesWhateverTheThreadCount) {
  // 3 m sphere distance at 1920 px: near drops become spheres, so both vectors are appended
  // chunk by chunk (chunks of 4096 drops: 15 chunks, the last one partial).
  ExportParams look = default_look();
  look.min_streak_coverage = 0.0;
  look.sphere_distance_m = 3.0;
  look.width = 1920;
  look.height = 1080;
  look.camera.exposure_s = 0.0;  // near drops stay spheres
  const sim::Frame frame =
      test_support::synthetic_rain(60000, look.camera, 16.0 / 9.0, 12.0, 2.0, 3);
  const FrameValues one = build_frame_values(frame, look, {}, 1);
  ASSERT_GT(one.drops.size(), 100u);
  ASSERT_GT(one.streaks.size(), 40000u);
  for (const int threads : {2, 3}) {
    EXPECT_EQ(differences(one, build_frame_values(frame, look, {}, threads)), 0u) << threads;
  }
  // Reusing a FrameValues that holds another frame gives the same values too.
  FrameValues reused =
      build_frame_values(test_support::synthetic_rain(5000, look.camera, 16.0 / 9.0), look);
  build_frame_values(frame, look, reused, {}, 2);
  EXPECT_EQ(differences(one, reused), 0u);
}

TEST(FrameValues, DegenerateCameraThrows) {
  ExportParams look = default_look();
  look.camera.look_at = look.camera.position;
  EXPECT_THROW(build_frame_values(sim::Frame{}, look), std::invalid_argument);
}

}  // namespace
}  // namespace raintrace::povgen
