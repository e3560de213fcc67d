// libFuzzer target on the scene loader's string entry point (tinyobjloader's habit): any input
// must either load or throw SceneError with a one-line message; anything else (a crash, a
// sanitizer report, another exception type, a multi-line message, a loaded scene that breaks a
// cross-field rule or that the parameter tables' own checks refuse) is a bug.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include "cli/scene.h"
#include "sim/param_table.h"
#include "sim/params.h"

namespace {

std::filesystem::path g_base_dir;

void require(bool condition) {
  if (!condition) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  // A real folder with includes in it, so the include checks run past "no such file".
  namespace fs = std::filesystem;
  g_base_dir = fs::temp_directory_path() / "raintrace_fuzz_scene";
  fs::create_directories(g_base_dir / "env");
  std::ofstream(g_base_dir / "street.inc") << "// fuzz\n";
  std::ofstream(g_base_dir / "env" / "field.inc") << "// fuzz\n";
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const raintrace::cli::Scene scene =
        raintrace::cli::load_scene_string(text, "fuzz.toml", g_base_dir);
    const auto& rain = scene.sim.rain;
    require(rain.diameter_min_mm <= rain.diameter_max_mm);
    require(rain.far_m > rain.near_m);
    require(scene.sim.lightning.distance_min_m <= scene.sim.lightning.distance_max_m);
    require(scene.sim.camera.position != scene.sim.camera.look_at);
    require(scene.look.camera.aspect == scene.sim.camera.aspect);
    // What the reader accepts, the checks of params made in code accept too.
    try {
      raintrace::sim::validate(scene.sim);
      raintrace::sim::check_params<raintrace::povgen::ExportParams>(
          raintrace::povgen::kExportParams, scene.look);
      raintrace::sim::check_params<raintrace::povgen::FogParams>(raintrace::povgen::kFogParams,
                                                                 scene.look.fog);
    } catch (const std::invalid_argument&) {
      require(false);
    }
    const std::string& include = scene.look.environment.include_path;
    require(include.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                      "0123456789_./-") == std::string::npos);
    require(include.empty() || (include.front() != '/' && include.rfind("..", 0) != 0));
  } catch (const raintrace::cli::SceneError& e) {
    const std::string_view message = e.what();
    require(message.find('\n') == std::string_view::npos);
    require(message.rfind("fuzz.toml:", 0) == 0);
  }
  return 0;
}
