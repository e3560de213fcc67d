// `raintrace simulate SCENE.toml [--frames A-B] [--seed N] [--stats FILE.json] [--threads N]
// [--max-memory SIZE] [--max-drop-steps N]`: runs the simulation alone (no POV-Ray), feeds every
// frame of the range to sim's StatisticsCollector, prints a one-line summary and optionally
// writes the statistics as JSON. Useful to check a scene's drop count and rain rate before
// paying for a render. A scene past the work or memory limits stops before it starts, as in
// export and render.
#include <fmt/core.h>
#include <unistd.h>
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>

#include "cli/command.h"
#include "cli/exit_codes.h"
#include "cli/folder_run.h"
#include "cli/options.h"
#include "cli/scene.h"
#include "cli/scene_error.h"
#include "sim/statistics.h"
#include "sim/world.h"

namespace raintrace::cli {
namespace {

struct SimulateArgs {
  std::string scene;
  std::string frames;
  std::optional<std::uint64_t> seed;  ///< none: the scene file's seed
  std::string stats;
  int threads = 0;
  LimitArgs limits;
};

constexpr const char* kSimulateFooter = R"(
Examples:
  raintrace simulate examples/default.toml                     # all frames, one-line summary
  raintrace simulate examples/default.toml --frames 1-24       # frames 1 to 24 (or one: 7)
  raintrace simulate examples/default.toml --seed 42           # another random rain, same scene
  raintrace simulate examples/default.toml --stats stats.json  # also write the statistics
  raintrace simulate examples/default.toml --stats -           # statistics to stdout
  raintrace simulate examples/default.toml --threads 1         # same numbers, one thread

Frames before the range are simulated too (the state depends on them) but not counted.
JSON (every field explained in docs/statistics.md): frames, dt_s,
drops {count, mean_diameter_mm, number_density_per_m3},
rain_rate_mm_per_h {configured, measured_at_ground}, fall_speed_by_diameter (0.1 mm bins)
[{diameter_min_mm, diameter_max_mm, mean_diameter_mm, speed_m_per_s, speed_sd_m_per_s,
samples}], horizontal_velocity_m_per_s [x, z], horizontal_motion_by_frame
[{time_s, drop_velocity_m_per_s [x, z], drop_velocity_sd_m_per_s [x, z],
wind_m_per_s [x, z]}], splashes,
ground {impacts, splashes, ripples, impacts_simulated, area_m2, impacts_per_m2_s},
lightning {strikes, segments}, plus scene, seed, frame_range, time_s, raintrace_version.
A scene asking for more memory or simulation than --max-memory/--max-drop-steps allow
stops before it starts, naming the scene keys to change.
Exit codes: 0 done, 2 bad scene file, option, or a scene past those limits.)";

/// Progress on stderr: a self-updating line on a terminal, a plain line every few seconds
/// otherwise (logs, CI), nothing for runs shorter than that.
class Progress {
 public:
  explicit Progress(int total) : m_total(total), m_terminal(isatty(fileno(stderr)) != 0) {}

  void update(int done) {
    const auto now = std::chrono::steady_clock::now();
    const double since_last = std::chrono::duration<double>(now - m_last).count();
    if (since_last < (m_terminal ? 0.1 : 5.0) && done < m_total) return;
    const double elapsed = std::chrono::duration<double>(now - m_start).count();
    if (!m_terminal && elapsed < 5.0) return;
    m_last = now;
    const int percent = m_total > 0 ? 100 * done / m_total : 100;
    if (m_terminal) {
      constexpr int kWidth = 30;
      const int filled = kWidth * percent / 100;
      fmt::print(stderr, "\rsimulate: [{}{}] {}/{} frames  {:.1f} s", std::string(filled, '#'),
                 std::string(kWidth - filled, '-'), done, m_total, elapsed);
      m_drawn = true;
    } else {
      fmt::print(stderr, "simulate: {}/{} frames ({}%), {:.1f} s elapsed\n", done, m_total, percent,
                 elapsed);
    }
    std::fflush(stderr);
  }

  /// Clears the self-updating line so the summary starts on a clean line.
  void finish() {
    if (m_drawn) fmt::print(stderr, "\r\033[K");
  }

 private:
  int m_total;
  bool m_terminal;
  bool m_drawn = false;
  std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point m_last{};
};

nlohmann::json statistics_json(const sim::Statistics& stats, const Scene& scene,
                               const FrameRange& range) {
  nlohmann::json bins = nlohmann::json::array();
  for (const sim::SpeedBin& bin : stats.fall_speed) {
    if (bin.samples == 0) continue;  // empty bins carry no measurement
    bins.push_back({{"diameter_min_mm", bin.diameter_min_mm},
                    {"diameter_max_mm", bin.diameter_max_mm},
                    {"mean_diameter_mm", bin.mean_diameter_mm},
                    {"speed_m_per_s", bin.speed_m_per_s},
                    {"speed_sd_m_per_s", bin.speed_sd_m_per_s},
                    {"samples", bin.samples}});
  }
  nlohmann::json motion = nlohmann::json::array();
  for (const sim::FrameMotion& m : stats.motion) {
    motion.push_back(
        {{"time_s", m.time_s},
         {"drop_velocity_m_per_s", {m.drop_velocity_m_per_s[0], m.drop_velocity_m_per_s[1]}},
         {"drop_velocity_sd_m_per_s",
          {m.drop_velocity_sd_m_per_s[0], m.drop_velocity_sd_m_per_s[1]}},
         {"wind_m_per_s", {m.wind_m_per_s[0], m.wind_m_per_s[1]}}});
  }
  return {
      {"frames", stats.frames},
      {"dt_s", stats.dt_s},
      {"drops",
       {{"count", stats.drop_count},
        {"mean_diameter_mm", stats.mean_diameter_mm},
        {"number_density_per_m3", stats.number_density_per_m3}}},
      {"rain_rate_mm_per_h",
       {{"configured", stats.rain_rate_configured_mm_per_h},
        {"measured_at_ground", stats.rain_rate_measured_mm_per_h}}},
      {"fall_speed_by_diameter", bins},
      {"horizontal_velocity_m_per_s",
       {stats.mean_horizontal_velocity_m_per_s[0], stats.mean_horizontal_velocity_m_per_s[1]}},
      {"horizontal_motion_by_frame", motion},
      {"splashes", stats.splashes},
      {"ground",
       {{"impacts", stats.ground.impacts},
        {"splashes", stats.ground.splashes},
        {"ripples", stats.ground.ripples},
        {"impacts_simulated", stats.ground.impacts_simulated},
        {"area_m2", stats.ground.area_m2},
        {"impacts_per_m2_s", stats.ground.impacts_per_m2_s}}},
      {"lightning", {{"strikes", stats.lightning_strikes}, {"segments", stats.lightning_segments}}},
      {"scene", scene.source.string()},
      {"seed", scene.sim.seed},
      {"frame_range", {range.first, range.last}},
      {"time_s", {(range.first - 1) / scene.look.fps, (range.last - 1) / scene.look.fps}},
      {"raintrace_version", RAINTRACE_VERSION},
  };
}

/// Writes next to the target and renames, so a reader never sees half a file.
void write_file_atomically(const std::filesystem::path& path, const std::string& text) {
  const std::filesystem::path temporary = path.string() + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out) throw std::runtime_error(fmt::format("cannot write {}", temporary.string()));
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    throw std::runtime_error(fmt::format("cannot write {}: {}", path.string(), error.message()));
  }
}

int run_simulate(const SimulateArgs& args) {
  Scene scene = load_scene_file(args.scene);
  if (args.seed) scene.sim.seed = *args.seed;
  scene.sim.threads = args.threads;
  const FrameRange range = parse_frame_range(args.frames, scene.frames);
  check_run_budget(scene_to_export(scene), {range.first, range.last}, 0, args.limits);

  sim::World world(scene.sim);
  sim::StatisticsCollector collector(scene.sim);
  Progress progress(range.last);
  for (int n = 1; n <= range.last; ++n) {
    // Frame n shows the world at (n − 1)/fps, as in the exporter.
    world.advance_to((n - 1) / scene.look.fps);
    if (n >= range.first) collector.add(world.snapshot(n));
    progress.update(n);
  }
  progress.finish();

  const sim::Statistics stats = collector.result();
  const bool stats_to_stdout = args.stats == "-";
  if (!args.stats.empty()) {
    const std::string text = statistics_json(stats, scene, range).dump(2) + "\n";
    if (stats_to_stdout) {
      fmt::print("{}", text);
    } else {
      write_file_atomically(args.stats, text);
    }
  }
  // With the JSON on stdout the summary goes to stderr, so stdout stays parseable.
  std::FILE* summary = stats_to_stdout ? stderr : stdout;
  fmt::print(summary,
             "simulated frames {}-{} of {} (seed {}): {:.0f} drops in view ({:.0f} per m3, mean "
             "{:.2f} mm), rain {:.2f} mm/h at the ground (configured {:g}), {} drops reached "
             "the visible ground, {} splashed, {} rippled puddles, {} lightning strikes\n",
             range.first, range.last, scene.source.string(), scene.sim.seed, stats.drop_count,
             stats.number_density_per_m3, stats.mean_diameter_mm, stats.rain_rate_measured_mm_per_h,
             stats.rain_rate_configured_mm_per_h, stats.ground.impacts, stats.ground.splashes,
             stats.ground.ripples, stats.lightning_strikes);
  return exit_code::ok;
}

}  // namespace

Command register_simulate_command(CLI::App& app) {
  auto args = std::make_shared<SimulateArgs>();
  auto* sub = app.add_subcommand(
      "simulate", "Simulate a scene without rendering and print (or save) its rain statistics");
  sub->footer(kSimulateFooter);
  sub->add_option("scene", args->scene, "Scene file (TOML, see docs/scene-format.md)")->required();
  sub->add_option("--frames", args->frames, "Frames to count: A-B or N (default: all)");
  add_seed_option(*sub, args->seed);
  sub->add_option("--stats", args->stats, "Write statistics as JSON to this file ('-': stdout)");
  sub->add_option("--threads", args->threads, "Worker threads, 0 = all cores (same results)")
      ->check(whole_number_in(0, 1024));
  add_limit_options(*sub, args->limits);
  return {sub, [args] { return run_simulate(*args); }};
}

}  // namespace raintrace::cli
