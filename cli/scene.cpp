// The scene file → Scene (sim::SimParams + povgen::ExportParams). Each section is read by one
// function below; a key absent from the file keeps the params struct's default member value, so
// defaults live in one place. The format, with every key, unit and range, is in
// docs/scene-format.md; the ranges here follow the `///` comments of sim/params.h,
// sim/camera.h and povgen/export_params.h.
//
//   seed = 7
//   [output]   frames = 48   fps = 24   width = 640   height = 360   quality = "preview"
//   [camera]   position = [0, 1.6, -5]   look_at = [0, 1.6, 0]   fov_deg = 60
//   [rain]     rate_mm_per_h = 5   distribution = "marshall-palmer"   …
#include "cli/scene.h"

#include <fmt/core.h>
#include <cmath>
#include <fstream>
#include <glm/geometric.hpp>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "cli/scene_document.h"
#include "cli/scene_error.h"
#include "cli/scene_include.h"
#include "cli/scene_reader.h"

namespace raintrace::cli {
namespace {

/// Positions are metres from the origin; beyond 100 km single-precision drop coordinates in
/// the frame and POV-Ray's own precision stop resolving millimetre drops.
const Range kCoordinate = Range::closed(-1e5, 1e5);
const Range kUnit = Range::closed(0.0, 1.0);

void read_output(TableReader r, Scene& scene) {
  r.read_integer("frames", scene.frames, 1, 100000);
  r.read_number("fps", scene.look.fps, Range::open_closed(0.0, 240.0));
  r.read_integer("width", scene.look.width, 16, 8192);
  r.read_integer("height", scene.look.height, 16, 8192);
  r.read_enum("quality", scene.look.quality,
              {{"preview", povgen::Quality::preview}, {"final", povgen::Quality::final}});
  r.finish();
}

void read_camera(TableReader r, sim::Camera& camera, double& aperture_m) {
  r.read_vec3("position", camera.position, kCoordinate);
  r.read_vec3("look_at", camera.look_at, kCoordinate);
  r.read_number("fov_deg", camera.fov_deg, Range::open(1.0, 170.0));
  r.read_number("exposure_s", camera.exposure_s, Range::closed(0.0, 1.0));
  r.read_number("aperture_m", aperture_m, Range::closed(0.0, 1.0));
  const glm::dvec3 view = camera.look_at - camera.position;
  if (glm::length(view) < 1e-6) {
    r.fail(
        r.where("look_at") ? "look_at" : "position",
        fmt::format("must differ from camera.position and camera.look_at (both are [{}, {}, {}])",
                    camera.position.x, camera.position.y, camera.position.z));
  }
  // POV-Ray's camera keeps +y up (sky); looking straight up or down leaves it no right vector.
  if (std::hypot(view.x, view.z) < 1e-6 * glm::length(view)) {
    r.fail(r.where("look_at") ? "look_at" : "position",
           "must not lie straight above or below camera.position (the camera keeps +y up)");
  }
  r.finish();
}

void read_rain(TableReader r, sim::RainParams& rain) {
  r.read_number("rate_mm_per_h", rain.rate_mm_per_h, Range::closed(0.0, 500.0));
  r.read_enum("distribution", rain.distribution,
              {{"marshall-palmer", sim::DropSizeDistribution::marshall_palmer},
               {"uniform", sim::DropSizeDistribution::uniform}});
  r.read_number("diameter_min_mm", rain.diameter_min_mm, Range::closed(0.1, 8.0));
  r.read_number("diameter_max_mm", rain.diameter_max_mm, Range::closed(0.1, 8.0));
  if (rain.diameter_min_mm > rain.diameter_max_mm) {
    r.fail(r.where("diameter_max_mm") ? "diameter_max_mm" : "diameter_min_mm",
           fmt::format("rain.diameter_min_mm must be <= rain.diameter_max_mm, got {} > {}",
                       rain.diameter_min_mm, rain.diameter_max_mm));
  }
  r.read_number("near_m", rain.near_m, Range::open(0.0, 1000.0));
  r.read_number("far_m", rain.far_m, Range::open_closed(0.0, 1000.0));
  if (rain.far_m <= rain.near_m) {
    r.fail(r.where("far_m") ? "far_m" : "near_m",
           fmt::format("rain.far_m must be > rain.near_m, got {} <= {}", rain.far_m, rain.near_m));
  }
  r.read_number("ceiling_margin_m", rain.ceiling_margin_m, Range::closed(0.0, 1000.0));
  r.read_bool("merging", rain.merging);
  r.read_number("breakup_diameter_mm", rain.breakup_diameter_mm, Range::closed(4.0, 10.0));
  r.read_number("vanishing_rate_per_s", rain.vanishing_rate_per_s, Range::closed(0.0, 100.0));
  r.read_vec3("colour", rain.colour, kUnit);
  r.finish();
}

void read_wind(TableReader r, sim::WindParams& wind) {
  r.read_vec3("velocity_m_per_s", wind.velocity_m_per_s, Range::closed(-60.0, 60.0));
  r.read_bool("gusts", wind.gusts);
  r.read_number("gust_strength", wind.gust_strength, Range::closed(0.0, 500.0));
  glm::dvec3 direction = wind.gust_direction;
  if (r.read_vec3("gust_direction", direction, Range::closed(-1000.0, 1000.0))) {
    const double horizontal = std::hypot(direction.x, direction.z);
    if (horizontal < 1e-9) {
      r.fail("gust_direction", "must point somewhere horizontally (x or z not 0; y is ignored)");
    }
    wind.gust_direction = {direction.x / horizontal, 0.0, direction.z / horizontal};
  }
  r.read_number("turbulence_m_per_s", wind.turbulence_m_per_s, Range::closed(0.0, 30.0));
  r.read_number("turbulence_scale_m", wind.turbulence_scale_m, Range::closed(0.1, 100.0));
  r.finish();
}

void read_splashes(TableReader r, sim::SplashParams& splashes) {
  r.read_bool("enabled", splashes.enabled);
  r.read_integer("droplets", splashes.droplets, 0, 32);
  r.read_number("lifetime_s", splashes.lifetime_s, Range::open_closed(0.0, 2.0));
  r.finish();
}

void read_lightning(TableReader r, sim::LightningParams& lightning, double& light) {
  r.read_bool("enabled", lightning.enabled);
  r.read_number("strikes_per_minute", lightning.strikes_per_minute, Range::closed(0.0, 600.0));
  r.read_integer("generations", lightning.generations, 1, 8);
  r.read_number("cloud_height_m", lightning.cloud_height_m, Range::closed(10.0, 5000.0));
  r.read_number("azimuth_deg", lightning.azimuth_deg, Range::closed(-180.0, 180.0));
  r.read_number("azimuth_spread_deg", lightning.azimuth_spread_deg, Range::closed(0.0, 180.0));
  r.read_number("distance_m", lightning.distance_m, Range::closed(0.0, 10000.0));
  r.read_number("distance_min_m", lightning.distance_min_m, Range::closed(0.0, 10000.0));
  r.read_number("distance_max_m", lightning.distance_max_m, Range::closed(0.0, 10000.0));
  if (lightning.distance_min_m > lightning.distance_max_m) {
    r.fail(r.where("distance_max_m") ? "distance_max_m" : "distance_min_m",
           fmt::format("lightning.distance_min_m must be <= lightning.distance_max_m, got {} > {}",
                       lightning.distance_min_m, lightning.distance_max_m));
  }
  r.read_number("trunk_radius_m", lightning.trunk_radius_m, Range::open_closed(0.0, 10.0));
  r.read_integer("return_strokes", lightning.return_strokes, 1, 10);
  r.read_number("flash_duration_s", lightning.flash_duration_s, Range::closed(0.05, 2.0));
  // Negative means "no forced strike"; the upper bound only keeps the number sane.
  r.read_number("first_strike_s", lightning.first_strike_s,
                Range{-std::numeric_limits<double>::infinity(), 1e6});
  r.read_number("light", light, Range::closed(0.0, 100.0));
  r.finish();
}

void read_fog(TableReader r, povgen::FogParams& fog) {
  r.read_enum("mode", fog.mode,
              {{"off", povgen::FogMode::off},
               {"ground", povgen::FogMode::ground},
               {"media", povgen::FogMode::media}});
  r.read_number("depth_m", fog.depth_m, Range::open_closed(0.0, 1000.0));
  r.read_number("density_per_m", fog.density_per_m, Range::closed(0.0, 5.0));
  r.read_vec3("colour", fog.colour, kUnit);
  r.finish();
}

void read_environment(TableReader r, povgen::EnvironmentParams& environment,
                      const std::filesystem::path& base_dir) {
  std::string name;
  if (r.read_enum("name", name,
                  {{"night_street", "night_street"}, {"field", "field"}, {"closeup", "closeup"}})) {
    environment.name = name;
  }
  std::string include;
  if (r.read_string("include", include)) {
    try {
      environment.include_path = validate_include_path(include, base_dir).generic_string();
    } catch (const std::invalid_argument& e) {
      r.fail("include", e.what());
    }
  }
  r.finish();
}

void read_export(TableReader r, povgen::ExportParams& look) {
  r.read_number("sphere_distance_m", look.sphere_distance_m, Range::closed(0.0, 1000.0));
  r.read_number("min_streak_coverage", look.min_streak_coverage, Range::closed(0.0, 1.0));
  r.read_number("splash_keep", look.splash_keep, Range::open_closed(0.0, 1.0));
  r.read_bool("environment_plate", look.environment_plate);
  r.read_bool("mask", look.mask);
  r.finish();
}

void read_simulation(TableReader r, sim::SimParams& sim) {
  r.read_number("substep_s", sim.substep_s, Range::closed(1e-4, 0.02));
  r.read_number("prewarm_s", sim.prewarm_s, Range::closed(0.0, 60.0));
  r.read_number("ground_y_m", sim.ground_y_m, kCoordinate);
  r.finish();
}

}  // namespace

Scene load_scene_string(std::string_view toml_text, const std::string& source_name,
                        const std::filesystem::path& base_dir) {
  Scene scene;
  scene.source = source_name;
  scene.text = std::string{toml_text};
  scene.base_dir = base_dir;
  const SceneNode document = parse_scene_document(toml_text, source_name);

  TableReader root(document, "", source_name);
  root.read_unsigned("seed", scene.sim.seed);
  read_output(root.section("output"), scene);
  read_camera(root.section("camera"), scene.sim.camera, scene.look.aperture_m);
  read_rain(root.section("rain"), scene.sim.rain);
  read_wind(root.section("wind"), scene.sim.wind);
  read_splashes(root.section("splashes"), scene.sim.splashes);
  read_lightning(root.section("lightning"), scene.sim.lightning, scene.look.lightning_light);
  read_fog(root.section("fog"), scene.look.fog);
  read_environment(root.section("environment"), scene.look.environment, base_dir);
  read_export(root.section("export"), scene.look);
  read_simulation(root.section("simulation"), scene.sim);
  root.finish();

  scene.sim.camera.aspect = static_cast<double>(scene.look.width) / scene.look.height;
  scene.look.camera = scene.sim.camera;
  return scene;
}

Scene load_scene_file(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  const std::string name = path.string();
  // A scene file is a few kilobytes; refusing huge ones keeps a wrong argument (a video, a
  // disk image) from eating memory.
  constexpr std::uintmax_t kMaxBytes = 16u << 20;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (error || !fs::exists(status)) {
    throw SceneError(scene_error_text(name, {}, "", "cannot read the scene file: no such file"));
  }
  if (!fs::is_regular_file(status)) {
    throw SceneError(
        scene_error_text(name, {}, "", "cannot read the scene file: not a regular file"));
  }
  if (fs::file_size(path, error) > kMaxBytes || error) {
    throw SceneError(scene_error_text(
        name, {}, "", fmt::format("cannot read the scene file: larger than {} bytes", kMaxBytes)));
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (!in) {
    throw SceneError(scene_error_text(name, {}, "", "cannot read the scene file"));
  }
  fs::path base_dir = path.parent_path();
  if (base_dir.empty()) base_dir = ".";
  return load_scene_string(bytes.str(), name, fs::absolute(base_dir, error));
}

}  // namespace raintrace::cli
