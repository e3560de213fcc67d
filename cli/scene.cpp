// The scene file → Scene (sim::SimParams + povgen::ExportParams). Every key is a row of a
// parameter table (sim/param_table.h) beside the struct it fills; scene_tables.h lists the
// tables. This file walks them section by section: each row is read with its type and range,
// order rules between keys are checked once their section is read, and the few rules that are
// not a range (the camera's direction, the gust direction, the environment include) follow.
// A key absent from the file keeps its struct's default member value.
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
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <type_traits>
#include <variant>

#include "cli/scene_document.h"
#include "cli/scene_error.h"
#include "cli/scene_include.h"
#include "cli/scene_reader.h"
#include "cli/scene_tables.h"
#include "povgen/environment_lamps.h"

namespace raintrace::cli {
namespace {

template <class P>
void read_param(TableReader& r, const sim::Param<P>& row, P& object) {
  std::visit(
      [&](const auto& field) {
        using Field = std::decay_t<decltype(field)>;
        if constexpr (std::is_same_v<Field, double P::*>) {
          r.read_number(row.key, object.*field, row.range);
        } else if constexpr (std::is_same_v<Field, int P::*>) {
          r.read_integer(row.key, object.*field, static_cast<int>(row.range.min),
                         static_cast<int>(row.range.max));
        } else if constexpr (std::is_same_v<Field, std::uint64_t P::*>) {
          r.read_unsigned(row.key, object.*field);
        } else if constexpr (std::is_same_v<Field, bool P::*>) {
          r.read_bool(row.key, object.*field);
        } else if constexpr (std::is_same_v<Field, glm::dvec3 P::*>) {
          r.read_vec3(row.key, object.*field, row.range);
        } else if constexpr (std::is_same_v<Field, std::string P::*>) {
          r.read_string(row.key, object.*field);
        } else {
          static_assert(std::is_same_v<Field, sim::ChoiceField<P>>);
          if (const auto index = r.read_choice(row.key, field.names)) {
            field.set(object, field.names, *index);
          }
        }
      },
      row.field);
}

/// Reads the rows of `table` in the reader's section into `object`, then checks their order
/// rules, blaming the later of the two keys when the file has it.
template <class P>
void read_params(TableReader& r, std::span<const sim::Param<P>> table, P& object) {
  for (const sim::Param<P>& row : table) {
    if (row.section == r.section_name()) read_param(r, row, object);
  }
  for (const sim::Param<P>& row : table) {
    if (row.section != r.section_name() || row.order == sim::Order::none) continue;
    const sim::Param<P>& other = *sim::find_param(table, row.section, row.other);
    const double value = sim::number_value(row, object);
    const double other_value = sim::number_value(other, object);
    const sim::OrderWords words = sim::order_words(row.order, value, other_value);
    if (words.holds) continue;
    const std::string_view later = &row > &other ? row.key : other.key;
    const std::string_view earlier = &row > &other ? other.key : row.key;
    r.fail(r.where(later) ? later : earlier,
           fmt::format("{} must be {} {}, got {} {} {}", r.full_key(row.key), words.wanted,
                       r.full_key(other.key), value, words.got, other_value));
  }
}

/// A bladed iris is a polygon: three blades at least. Its spikes' length comes from the opening's
/// size, so it needs one.
void check_aperture_blades(const TableReader& r, const Scene& scene) {
  const int blades = scene.develop.aperture_blades;
  if (!film::is_blade_count(blades)) {  // the table's range leaves only 1 and 2
    r.fail("aperture_blades", fmt::format("must be 0 (a round opening) or 3 to {} blades, got {}",
                                          film::kMaxApertureBlades, blades));
  }
  if (blades != 0 && !(scene.look.aperture_m > 0.0)) {
    r.fail("aperture_blades",
           "needs camera.aperture_m > 0: the spikes' length comes from the opening's size");
  }
}

/// The lens barrel's rim clips the rays a traced focal blur spreads over the opening; a pinhole,
/// or rain blurred without tracing, has no such rays to clip.
void check_optical_vignetting(const TableReader& r, const Scene& scene) {
  if (scene.look.optical_vignetting > 0.0 && !povgen::traces_focal_blur(scene.look)) {
    r.fail("optical_vignetting",
           "needs a traced focal blur: camera.aperture_m > 0 and camera.focal_blur = \"traced\"");
  }
}

/// A white balance is a colour temperature on the Planckian locus, or off.
void check_white_balance(const TableReader& r, const Scene& scene) {
  const double kelvin = scene.develop.white_balance_k;
  if (kelvin != 0.0 && kelvin < film::kMinWhiteBalanceK) {  // the table's range leaves (0, 2000)
    r.fail("white_balance_k",
           fmt::format("must be 0 (off: D65 white, the colours as traced) or in [{}, {}] K, got {}",
                       film::kMinWhiteBalanceK, film::kMaxWhiteBalanceK, kelvin));
  }
}

/// Where to blame a camera problem: look_at when the file gives it, else position.
std::string_view camera_key(const TableReader& r) {
  return r.where("look_at") ? "look_at" : "position";
}

void check_camera(const TableReader& r, const sim::Camera& camera) {
  if (!sim::has_view_direction(camera)) {
    const std::string_view key = camera_key(r);
    r.fail(key, fmt::format("must differ from camera.{} (both are [{}, {}, {}])",
                            key == "look_at" ? "position" : "look_at", camera.position.x,
                            camera.position.y, camera.position.z));
  }
  // POV-Ray's camera keeps +y up (sky); looking straight up or down leaves it no right vector.
  if (sim::looks_straight_up_or_down(camera)) {
    r.fail(camera_key(r),
           "must not lie straight above or below camera.position (the camera keeps +y up)");
  }
}

/// The gust direction's horizontal part, normalised (y is ignored).
void normalise_gust_direction(const TableReader& r, sim::WindParams& wind) {
  if (!r.where("gust_direction")) return;
  glm::dvec3& direction = wind.gust_direction;
  if (!sim::is_horizontal_direction(direction)) {
    r.fail("gust_direction", "must point somewhere horizontally (x or z not 0; y is ignored)");
  }
  const double horizontal = std::hypot(direction.x, direction.z);
  direction = {direction.x / horizontal, 0.0, direction.z / horizontal};
}

void check_include(const TableReader& r, povgen::EnvironmentParams& environment,
                   const std::filesystem::path& base_dir) {
  if (!r.where("include")) return;
  try {
    environment.include_path =
        validate_include_path(environment.include_path, base_dir).generic_string();
  } catch (const std::invalid_argument& e) {
    r.fail("include", e.what());
  }
}

/// night_street's puddles when the scene does not say: a quarter of the road under water, what a
/// street in steady rain shows (a choice of the look, not a measurement). Other environments
/// have no paved ground to hold them.
constexpr double kNightStreetPuddleCoverage = 0.25;

/// The ground povgen draws: the simulation's puddles ("automatic" coverage resolved), ripples
/// and ground height (the rain's rate it takes from look.rain).
void resolve_ground(Scene& scene) {
  sim::PuddleParams& puddles = scene.sim.puddles;
  if (puddles.coverage < 0.0) {
    const povgen::EnvironmentParams& environment = scene.look.environment;
    const bool street = environment.include_path.empty() && environment.name == "night_street";
    puddles.coverage = street ? kNightStreetPuddleCoverage : 0.0;
  }
  povgen::GroundLook& ground = scene.look.ground;
  ground.puddles = puddles;
  ground.ripples = scene.sim.ripples;
  ground.ground_y_m = scene.sim.ground_y_m;
}

/// Reads one section: the rows of every table in it, then the rules that are not a range.
void read_section(TableReader& r, Scene& scene) {
  for_each_table(scene, [&](auto table, auto& object) {
    read_params<std::remove_cvref_t<decltype(object)>>(r, table, object);
  });
  const std::string& section = r.section_name();
  if (section == "camera") {
    check_camera(r, scene.sim.camera);
    check_aperture_blades(r, scene);
    check_optical_vignetting(r, scene);
    check_white_balance(r, scene);
  }
  if (section == "wind") normalise_gust_direction(r, scene.sim.wind);
  if (section == "environment") check_include(r, scene.look.environment, scene.base_dir);
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
  for (const std::string_view section : kSections) {
    if (section.empty()) {
      read_section(root, scene);
      continue;
    }
    TableReader reader = root.section(section);
    read_section(reader, scene);
    reader.finish();
  }
  root.finish();

  set_image_size(scene, scene.look.width, scene.look.height);
  scene.look.rain = scene.sim.rain;
  resolve_ground(scene);
  if (scene.look.environment.include_path.empty()) {
    scene.sim.lamps = povgen::environment_lamps(scene.look.environment.name);
  }
  return scene;
}

void set_image_size(Scene& scene, int width, int height) {
  scene.look.width = width;
  scene.look.height = height;
  scene.sim.camera.aspect = static_cast<double>(width) / height;
  scene.sim.camera.width_px = width;
  scene.look.camera = scene.sim.camera;
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
