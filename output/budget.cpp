// The run budget: sim::World::estimate for the drops, the measured memory model for the bytes.
#include "output/budget.h"

#include <fmt/core.h>
#include <unistd.h>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <vector>

#include "povgen/frame_values.h"
#include "sim/frame.h"
#include "sim/lamp_rain.h"
#include "sim/world.h"

namespace raintrace::output {
namespace {

constexpr double kMiB = 1024.0 * 1024.0;
constexpr double kGiB = 1024.0 * kMiB;

// The measured model (budget.h), each term rounded up from what was measured.
constexpr double kSimulationBase = 240 * kMiB;  // rendering: developing frames adds to export's
constexpr double kSimulationPerDrop = 150.0;
constexpr double kSimulationPerLampDrop = 120.0;  // a lamp's World: no merging, nothing copied
constexpr double kPovrayBase = 56 * kMiB;         // the environment: meshes, textures, maps
constexpr double kPovrayPerPixel = 64.0;          // POV-Ray's image buffers
constexpr double kPovrayPerViewDropLod = 160.0;
constexpr double kPovrayPerViewDropAll = 600.0;  // every streak kept: a drop drawn
/// Drops of each lamp's ball sampled to see how many of them a frame draws.
constexpr int kLampSample = 4096;
/// The simulation's speed on the reference machine, for telling users how long a run is.
constexpr double kDropStepsPerSecond = 1e8;

// "42 million", "15 200", "2.3e16": counts for people.
std::string human_count(double n) {
  if (n < 1e4) return fmt::format("{:.0f}", n);
  if (n < 1e6) return fmt::format("{:.0f} thousand", n / 1e3);
  if (n < 1e9) return fmt::format("{:.3g} million", n / 1e6);
  if (n < 1e12) return fmt::format("{:.3g} billion", n / 1e9);
  const int exponent = static_cast<int>(std::floor(std::log10(n)));
  return fmt::format("{:.2g}e{}", n / std::pow(10.0, exponent), exponent);
}

// A number as an option takes it, short: "6.4e9".
std::string option_number(double n) {
  if (n < 1e6) return fmt::format("{:.0f}", std::ceil(n));
  const int exponent = static_cast<int>(std::floor(std::log10(n)));
  return fmt::format("{:.2g}e{}", std::ceil(n / std::pow(10.0, exponent - 1)) / 10.0, exponent);
}

std::string human_duration(double seconds) {
  if (seconds < 120) return fmt::format("{:.0f} s", seconds);
  if (seconds < 7200) return fmt::format("{:.0f} minutes", seconds / 60);
  if (seconds < 2 * 86400) return fmt::format("{:.0f} hours", seconds / 3600);
  if (seconds < 2 * 365 * 86400) return fmt::format("{:.0f} days", seconds / 86400);
  return fmt::format("{:.2g} years", seconds / (365 * 86400.0));
}

/// How many of the lamps' drops a frame draws. They lie 15 m and more away, where most streaks
/// fall below the coverage threshold and are thinned (povgen/frame_values.h): of a ball's
/// drops a frame draws a few percent. A sample of them goes through povgen's own choice.
double lamp_drops_drawn(const SceneToExport& scene) {
  sim::LampRain::Sample sample = sim::LampRain::sample(scene.sim, kLampSample);
  if (sample.drops.size() == 0) return 0.0;
  sim::Frame frame;
  frame.index = 1;
  frame.drops = std::move(sample.drops);
  const povgen::FrameValues values = povgen::build_frame_values(frame, scene.look);
  return static_cast<double>(values.drops.size() + values.streaks.size()) * sample.drops_per_sample;
}

}  // namespace

double default_max_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page = ::sysconf(_SC_PAGE_SIZE);
  const double physical =
      pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 8 * kGiB;
  return std::min(4 * kGiB, physical / 2);
}

Budget estimate_budget(const SceneToExport& scene, FrameSpan range, int povray_processes) {
  const sim::WorkEstimate work = sim::World::estimate(scene.sim);
  const sim::WorkEstimate lamps = sim::LampRain::estimate(scene.sim);
  Budget b;
  b.lamp_drops = lamps.drops;
  b.drops = work.drops + lamps.drops;
  b.lamp_drops_drawn = lamp_drops_drawn(scene);
  b.drops_in_view = work.drops_in_view + b.lamp_drops_drawn;
  b.substeps = work.steps_until((range.last - 1) / scene.look.fps, scene.sim.substep_s);
  b.drop_steps = b.drops * b.substeps;
  b.simulation_bytes =
      kSimulationBase + kSimulationPerDrop * work.drops + kSimulationPerLampDrop * lamps.drops;
  // Far streaks below the coverage threshold are thinned (povgen/frame_values.h): the lower it
  // is, the more are kept, up to all of them at 0. The model's 160 bytes were measured at the
  // preview's threshold, and a streak is kept with probability coverage / threshold, so a lower
  // threshold keeps proportionally more. An unset min_streak_coverage (< 0) is the quality's
  // own threshold; until 2026-12-05 it was budgeted as 0, every streak kept, at 600 bytes.
  const double threshold = povgen::streak_coverage_threshold(scene.look);
  const double per_view_drop =
      threshold <= 0.0
          ? kPovrayPerViewDropAll
          : std::min(kPovrayPerViewDropAll, kPovrayPerViewDropLod * povgen::kPreviewStreakCoverage /
                                                std::min(threshold, 1.0));
  b.povray_bytes = kPovrayBase + kPovrayPerPixel * scene.look.width * scene.look.height +
                   per_view_drop * work.drops_in_view + kPovrayPerViewDropAll * b.lamp_drops_drawn;
  b.povray_processes = std::max(0, povray_processes);
  return b;
}

void check_budget(const Budget& b, const BudgetLimits& limits) {
  if (!(b.drop_steps <= limits.max_drop_steps)) {
    throw BudgetExceeded(fmt::format(
        "this scene asks for {} drop-steps of simulation ({} drops × {} substeps up to the "
        "last frame), about {} at {} drop-steps/s, more than the limit of {}: raise "
        "[simulation] substep_s or [output] fps, lower [output] frames (or --frames) or "
        "[simulation] prewarm_s, or lower [rain] rate_mm_per_h, far_m or lamp_reach_m; or raise "
        "the limit with --max-drop-steps {}",
        human_count(b.drop_steps), human_count(b.drops), human_count(b.substeps),
        human_duration(b.drop_steps / kDropStepsPerSecond), human_count(kDropStepsPerSecond),
        human_count(limits.max_drop_steps), option_number(b.drop_steps * 1.5)));
  }
  const double max_memory =
      limits.max_memory_bytes > 0.0 ? limits.max_memory_bytes : default_max_memory_bytes();
  if (!(b.total_bytes() <= max_memory)) {
    const std::string povray =
        b.povray_processes > 0
            ? fmt::format(", POV-Ray {} × {} for {} drops in view", b.povray_processes,
                          format_bytes(b.povray_bytes), human_count(b.drops_in_view))
            : std::string{};
    throw BudgetExceeded(fmt::format(
        "this scene needs about {} of memory (simulation {} for {} drops{}), more than the "
        "limit of {}: lower [rain] far_m or rate_mm_per_h{}{}, or raise the limit with "
        "--max-memory {:.0f}G",
        format_bytes(b.total_bytes()), format_bytes(b.simulation_bytes), human_count(b.drops),
        povray, format_bytes(max_memory), b.lamp_drops > 0.0 ? " (or lamp_reach_m)" : "",
        b.povray_processes > 1 ? " (or --jobs)" : "", std::ceil(b.total_bytes() * 1.25 / kGiB)));
  }
}

std::optional<double> parse_byte_size(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) {
    text.remove_suffix(1);
  }
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || !(value > 0.0) || !std::isfinite(value)) return std::nullopt;
  std::string unit{end, text.data() + text.size()};
  std::transform(unit.begin(), unit.end(), unit.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  if (unit.size() >= 2 && unit.compare(unit.size() - 2, 2, "IB") == 0) {
    unit.erase(unit.size() - 2);  // "GiB"
  } else if (!unit.empty() && unit.back() == 'B') {
    unit.pop_back();  // "GB", "B"
  }
  static const std::vector<std::pair<std::string, double>> kUnits{
      {"", 1.0}, {"K", 1024.0}, {"M", kMiB}, {"G", kGiB}, {"T", 1024.0 * kGiB}};
  for (const auto& [name, factor] : kUnits) {
    if (unit == name) return value * factor;
  }
  return std::nullopt;
}

std::string format_bytes(double bytes) {
  if (bytes >= kGiB) return fmt::format("{:.1f} GB", bytes / kGiB);
  return fmt::format("{:.0f} MB", std::ceil(bytes / kMiB));
}

}  // namespace raintrace::output
