// The wet ground rendered by the real POV-Ray (ctest label `povray`; skipped without povray):
// ripples appear in the picture where their impacts were simulated and spread with time, and
// splashes carry on past the simulated volume of drops without an edge.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

/// A folder whose environment is kWetPlane, with frames 1..n from `frames`.
fs::path wet_folder(const std::string& name, const ExportParams& base,
                    const std::vector<sim::Frame>& frames) {
  const fs::path dir = testing::scratch_folder("povray_ground_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "wet.inc") << kWetPlane;
  ExportParams look = base;
  look.environment.include_path = "wet.inc";
  const std::string shared = write_shared_files(dir, look, static_cast<int>(frames.size()), dir);
  FrameValues values;
  for (const sim::Frame& frame : frames) {
    build_frame_values(frame, look, values);
    write_frame_file(dir / "frames" / frame_file_name("frame", frame.index, 4, ".pov"), values,
                     shared, 1);
  }
  return dir;
}

TEST(PovRayGround, RipplesAppearWhereTheirImpactsWereAndSpreadWithTime) {
  SKIP_WITHOUT_POVRAY();
  // The camera 1.6 m up looks at the ground 2.5 m ahead (a pixel spans ~2.5 mm there at 1280
  // pixels, so the 17 mm rings are drawn), all of it puddle, no rain roughness. A 4 mm drop's
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
  // … and spreads at the capillary-gravity ring speed, 0.231 m/s: 2.3 cm in 0.1 s (to a
  // quarter wavelength: the crests' reflections move in steps as they pass the sky's bands).
  EXPECT_NEAR(radius2 - radius1, sim::ripple_speed() * 0.1, 0.0045);
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
