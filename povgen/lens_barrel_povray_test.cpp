// The lens barrel's rim with the real POV-Ray: a point of light out of focus near a corner of the
// frame comes out as a cat's eye, narrowed toward the centre, with the share of its light that
// the hole lets through, while one in the middle keeps its whole disc.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "povgen/lens_barrel.h"
#include "povgen/povray_test_support.h"
#include "povgen/scene_files.h"

namespace raintrace::povgen {
namespace {

namespace fs = std::filesystem;

constexpr int kBarrelPixels = 200;
constexpr double kBarrelLightDepth = 10.0;  // m; the focus is at 1 m
constexpr double kFieldShare = 0.8;  // the corner's light: 0.8 of the way out along the diagonal

/// A square 20° camera at the origin looking along +z, focused at 1 m through a 4 cm opening.
ExportParams square_look(double optical_vignetting) {
  ExportParams look;
  look.width = look.height = kBarrelPixels;
  look.quality = Quality::final;
  look.camera.position = {0.0, 0.0, 0.0};
  look.camera.look_at = {0.0, 0.0, 1.0};
  look.camera.fov_deg = 20.0;
  look.aperture_m = 0.04;
  look.optical_vignetting = optical_vignetting;
  return look;
}

/// The camera line of scene.inc, the rim, and two small lights 10 m away: one on the axis, one
/// toward the top right corner.
std::string two_lights_scene(const ExportParams& look) {
  const std::string inc = scene_inc_text(look);
  const std::size_t camera = inc.find("camera{");
  const double t = kFieldShare * half_diagonal_tan(look) / std::sqrt(2.0);
  const std::string light = " 0.02 pigment{rgb 1} finish{ambient 0 diffuse 0 emission 1}}\n";
  return "#version 3.7;\nglobal_settings{assumed_gamma 1}\n" +
         inc.substr(camera, inc.find('\n', camera) - camera) + "\n" + lens_barrel_text(look) +
         "sphere{<0,0," + std::to_string(kBarrelLightDepth) + ">," + light + "sphere{<" +
         std::to_string(t * kBarrelLightDepth) + "," + std::to_string(t * kBarrelLightDepth) + "," +
         std::to_string(kBarrelLightDepth) + ">," + light;
}

/// A window's light and how it spreads along the diagonal toward the centre and across it.
struct DiscMoments {
  double light = 0.0;
  double radial_sd = 0.0;  // along (1, −1)/√2 in pixels, x right and y down: toward the corner
  double across_sd = 0.0;  // along (1, 1)/√2
};

DiscMoments disc_moments_in(const std::vector<float>& px, int x0, int y0, int size) {
  DiscMoments b;
  double sx = 0.0, sy = 0.0;
  for (int y = y0; y < y0 + size; ++y) {
    for (int x = x0; x < x0 + size; ++x) {
      const double v = px[3 * (y * kBarrelPixels + x) + 1];
      b.light += v;
      sx += v * x;
      sy += v * y;
    }
  }
  const double cx = sx / b.light, cy = sy / b.light;
  double radial = 0.0, across = 0.0;
  for (int y = y0; y < y0 + size; ++y) {
    for (int x = x0; x < x0 + size; ++x) {
      const double v = px[3 * (y * kBarrelPixels + x) + 1];
      const double r = ((x - cx) - (y - cy)) / std::sqrt(2.0);
      const double a = ((x - cx) + (y - cy)) / std::sqrt(2.0);
      radial += v * r * r;
      across += v * a * a;
    }
  }
  b.radial_sd = std::sqrt(radial / b.light);
  b.across_sd = std::sqrt(across / b.light);
  return b;
}

/// What the geometry says of the corner's disc: the share of the opening whose rays toward the
/// light pass the hole, and that part's spread along the diagonal over its spread across, from
/// the opening sampled on a fine grid.
struct RimGeometry {
  double share = 0.0;
  double radial_over_across = 0.0;
};

RimGeometry expected_corner_disc(const ExportParams& look) {
  const LensBarrel barrel = lens_barrel(look);
  const double opening_radius = look.aperture_m / 2.0;
  const double t = kFieldShare * half_diagonal_tan(look);  // the light's direction, along u
  const int n = 801;
  double all = 0.0, kept = 0.0, su = 0.0, sv = 0.0, suu = 0.0, svv = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double u = opening_radius * (2.0 * i / (n - 1) - 1.0);  // along the diagonal
      const double v = opening_radius * (2.0 * j / (n - 1) - 1.0);
      if (u * u + v * v > opening_radius * opening_radius) continue;
      all += 1.0;
      // The ray from (u, v) on the opening to the light at depth kBarrelLightDepth, at the rim.
      const double at = barrel.distance_m / kBarrelLightDepth;
      const double ru = u * (1.0 - at) + t * barrel.distance_m, rv = v * (1.0 - at);
      if (ru * ru + rv * rv > barrel.hole_radius_m * barrel.hole_radius_m) continue;
      kept += 1.0;
      su += u;
      sv += v;
      suu += u * u;
      svv += v * v;
    }
  }
  const double mu = su / kept, mv = sv / kept;
  return {kept / all, std::sqrt((suu / kept - mu * mu) / (svv / kept - mv * mv))};
}

TEST(PovRayLensBarrel, ACornersDiscOutOfFocusIsACatsEyeWithTheLightThroughTheHole) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::empty_scratch_folder("povray_test_lens_barrel");
  const std::string size = testing::square_size(kBarrelPixels) + " -A";
  const auto open = testing::trace_linear(dir, "open", two_lights_scene(square_look(0.0)), size);
  const auto rim = testing::trace_linear(dir, "rim", two_lights_scene(square_look(0.5)), size);
  ASSERT_EQ(open.size(), std::size_t{3 * kBarrelPixels * kBarrelPixels});
  ASSERT_EQ(rim.size(), open.size());

  // The corner's light lands about (180, 20); its disc is ~20 pixels across.
  const DiscMoments corner_open = disc_moments_in(open, 156, 0, 44);
  const DiscMoments corner_rim = disc_moments_in(rim, 156, 0, 44);
  const DiscMoments middle_open = disc_moments_in(open, 78, 78, 44);
  const DiscMoments middle_rim = disc_moments_in(rim, 78, 78, 44);
  const RimGeometry expected = expected_corner_disc(square_look(0.5));

  // Round without the rim (to the few per cent the light's own ball, seen off the axis, adds).
  const double open_shape = corner_open.radial_sd / corner_open.across_sd;
  EXPECT_NEAR(open_shape, 1.0, 0.06);
  // The middle's disc passes whole.
  EXPECT_NEAR(middle_rim.light / middle_open.light, 1.0, 0.02);
  EXPECT_NEAR(middle_rim.radial_sd / middle_open.radial_sd, 1.0, 0.03);
  // The corner's keeps the share of the opening the hole lets through (0.66 here; measured
  // 0.64), narrowed along the diagonal as that share of the opening is (0.68; measured 0.71).
  EXPECT_LT(expected.share, 0.9);
  EXPECT_NEAR(corner_rim.light / corner_open.light, expected.share, 0.04)
      << "expected " << expected.share;
  const double narrowing = corner_rim.radial_sd / corner_rim.across_sd / open_shape;
  EXPECT_NEAR(narrowing, expected.radial_over_across, 0.05)
      << "expected " << expected.radial_over_across;
  EXPECT_LT(narrowing, 0.8);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace raintrace::povgen
