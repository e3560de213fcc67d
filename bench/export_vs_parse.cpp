// What writing a frame costs against what POV-Ray then spends reading it. For frame 12 of
// several examples (simulated once, untimed) and a synthetic frame of 1 M drops in view:
// BM_FrameText times the text alone (the numbers and punctuation of frame_text.cpp, into a
// sink that only counts bytes); BM_ExportFrame what `raintrace export` does per frame once the
// simulation has run: frame values, text, hash and the file write. Both on one thread.
// BM_PovRayParse runs POV-Ray on that same file and reports the CPU seconds its own statistics
// give for the parse (the environment and materials included, as in every frame), with the
// counters text_share_pct and export_share_pct: each time / parse time × 100. Target: the text
// at most 5 % of the parse.
//   build/bench/export_vs_parse          (needs povray on PATH; ~1 min)
#include <benchmark/benchmark.h>

#include <cstdio>
#include <ctime>
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "cli/scene.h"
#include "povgen/export_params.h"
#include "povgen/frame_text.h"
#include "povgen/frame_values.h"
#include "povgen/output_folder.h"
#include "povgen/test_support/synthetic_rain.h"
#include "sim/world.h"

namespace {

using namespace raintrace;
namespace fs = std::filesystem;

constexpr int kFrame = 12;

/// A frame to write, its look, and the output folder it goes to (shared files written once).
struct Case {
  sim::Frame frame;
  povgen::ExportParams look;
  fs::path dir;
  std::string shared_hash;
  double text_seconds = 0.0;    ///< CPU seconds per frame, set by BM_FrameText
  double export_seconds = 0.0;  ///< CPU seconds per frame, set by BM_ExportFrame
};

/// CPU seconds per iteration of a benchmark loop that started at `start`.
double cpu_seconds_per_iteration(std::clock_t start, const benchmark::State& state) {
  return static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC /
         static_cast<double>(state.iterations());
}

std::map<std::string, Case>& cases() {
  static std::map<std::string, Case> all;
  return all;
}

Case make_case(const std::string& name, sim::Frame frame, const povgen::ExportParams& look,
               const fs::path& scene_dir) {
  Case c;
  c.frame = std::move(frame);
  c.look = look;
  c.dir = fs::temp_directory_path() / ("raintrace_export_vs_parse_" + name);
  fs::remove_all(c.dir);
  // One frame folder: frame kFrame alone, as a partial export would leave it.
  c.shared_hash = povgen::write_shared_files(c.dir, c.look, kFrame, scene_dir, {kFrame, kFrame});
  return c;
}

/// Frame kFrame of an example, simulated as `raintrace export` would.
Case example_case(const std::string& name) {
  const fs::path file = fs::path{RAINTRACE_SOURCE_DIR} / "examples" / (name + ".toml");
  const cli::Scene scene = cli::load_scene_file(file);
  sim::World world(scene.sim);
  world.advance_to((kFrame - 1) / scene.look.fps);
  return make_case(name, world.snapshot(kFrame), scene.look, file.parent_path());
}

void BM_FrameText(benchmark::State& state, const std::string& name) {
  Case& c = cases().at(name);
  const povgen::FrameValues values =
      povgen::build_frame_values(c.frame, c.look, povgen::StreakAtlasLayout{}, 1);
  std::size_t bytes = 0;
  const povgen::TextSink sink = [&bytes](std::string_view piece) { bytes += piece.size(); };
  const std::clock_t start = std::clock();
  for (auto _ : state) povgen::write_frame_text(values, sink, povgen::StreakAtlasLayout{}, 1);
  c.text_seconds = cpu_seconds_per_iteration(start, state);
  benchmark::DoNotOptimize(bytes);
}

void BM_ExportFrame(benchmark::State& state, const std::string& name) {
  Case& c = cases().at(name);
  const fs::path file = c.dir / "frames" / "frame_0012.pov";
  povgen::FrameValues values;
  const std::clock_t start = std::clock();
  for (auto _ : state) {
    povgen::build_frame_values(c.frame, c.look, values, povgen::StreakAtlasLayout{}, 1);
    benchmark::DoNotOptimize(povgen::write_frame_file(file, values, c.shared_hash, 1));
  }
  c.export_seconds = cpu_seconds_per_iteration(start, state);
  state.counters["drops"] = static_cast<double>(c.frame.drops.size());
  state.counters["streaks"] = static_cast<double>(values.streaks.size());
  state.counters["spheres"] = static_cast<double>(values.drops.size());  // splash droplets included
}

/// The "Parse Time" CPU seconds of one POV-Ray run on the folder's frame.
double povray_parse_seconds(const fs::path& dir) {
  const std::string command =
      "cd '" + dir.string() + "' && povray scene.ini -D +W16 +H9 -V +Oparse_check.png 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), &pclose);
  if (!pipe) throw std::runtime_error("cannot run povray");
  std::string output;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe.get()) != nullptr) output += buffer;
  // "  Parse Time: … (0.056 seconds)\n              using 1 thread(s) with 0.025 CPU-seconds"
  const std::size_t parse = output.find("Parse Time:");
  const std::size_t with = output.find("with ", parse);
  if (parse == std::string::npos || with == std::string::npos) {
    throw std::runtime_error("no parse statistics from povray:\n" + output);
  }
  return std::stod(output.substr(with + 5));
}

void BM_PovRayParse(benchmark::State& state, const std::string& name) {
  const Case& c = cases().at(name);
  if (c.export_seconds <= 0.0) {
    state.SkipWithError("run BM_FrameText and BM_ExportFrame first: the latter writes the frame");
    return;
  }
  double total = 0.0;
  for (auto _ : state) {
    const double seconds = povray_parse_seconds(c.dir);
    total += seconds;
    state.SetIterationTime(seconds);
  }
  const double parse = total / static_cast<double>(state.iterations());
  state.counters["text_share_pct"] = 100.0 * c.text_seconds / parse;
  state.counters["export_share_pct"] = 100.0 * c.export_seconds / parse;
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  std::vector<std::string> names;
  for (const char* example : {"light_rain", "default", "streaks", "heavy_rain", "thunderstorm"}) {
    cases().emplace(example, example_case(example));
    names.emplace_back(example);
  }
  // Every streak of a million drops in view: the text-heavy end.
  povgen::ExportParams every_streak;
  every_streak.min_streak_coverage = 0.0;
  cases().emplace("synthetic_1M",
                  make_case("synthetic_1M",
                            povgen::test_support::synthetic_rain(1'000'000, every_streak.camera,
                                                                 every_streak.camera.aspect),
                            every_streak, fs::temp_directory_path()));
  names.emplace_back("synthetic_1M");
  for (const std::string& name : names) {
    benchmark::RegisterBenchmark(("BM_FrameText/" + name).c_str(), BM_FrameText, name)
        ->Unit(benchmark::kMillisecond);
  }
  for (const std::string& name : names) {
    benchmark::RegisterBenchmark(("BM_ExportFrame/" + name).c_str(), BM_ExportFrame, name)
        ->Unit(benchmark::kMillisecond);
  }
  for (const std::string& name : names) {
    benchmark::RegisterBenchmark(("BM_PovRayParse/" + name).c_str(), BM_PovRayParse, name)
        ->Unit(benchmark::kMillisecond)
        ->UseManualTime()
        ->Iterations(3);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
