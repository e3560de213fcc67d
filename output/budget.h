// What a run will ask of the machine, known before anything starts: the simulation's work
// (drops × substeps) and the memory of raintrace and of the POV-Ray processes in flight. A run
// past a limit stops before it creates a file, with a message naming the scene keys to change
// and the option that raises the limit (--max-drop-steps, --max-memory).
//
// The memory model is measured, not derived (Debian 12, 2 cores; BENCHMARKS.md, "Memory of one
// run"). raintrace's peak RSS while exporting (rate_mm_per_h = 500, far_m = 6 / 8 / 10) was
// 302 / 425 / 637 MiB for 1.1 / 2.2 / 3.9 million simulated drops, i.e. ~180 MiB + 126 bytes
// a drop, and rendering (developing the frames) adds 40–90 MiB: 340 MiB at far_m = 6. A drop of
// the rain around the lamps (sim/lamp_rain.h: no merging, no copy for a frame) takes 82 bytes
// in its World, 111 in heavy_rain's render (2.85 million: 278 → 580 MiB).
// POV-Ray's peak on a frame without rain was 43–52 MiB for the examples at 160×90, 99–107 MiB
// at 1280×720 (~64 bytes a pixel), and each drop in view adds 110–150 bytes at the preview's
// streak level of detail, ~500 for a drop drawn (every streak kept). The estimate rounds these
// up: 240 MiB + 150 bytes a simulated drop (120 around the lamps); 56 MiB + 64 bytes a pixel +
// 160 bytes a drop in view at the preview's streak threshold, in inverse proportion to a lower
// one (final's keeps 3.3 times as many far streaks), 600 with every streak kept. Of the rain
// around the lamps, 15 m and more away, povgen draws a few percent: a sample of it goes through
// povgen's own choice (povgen::build_frame_values) and each drop drawn counts 600 bytes.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "output/export.h"

namespace raintrace::output {

struct Budget {
  double drops = 0.0;          ///< simulated drops at steady state
  double lamp_drops = 0.0;     ///< of those, the rain around the lamps (sim/lamp_rain.h)
  double drops_in_view = 0.0;  ///< of those, in the view frustum (what a frame writes)
  /// Of drops_in_view, those of the rain around the lamps (sim/lamp_rain.h) that a frame draws.
  double lamp_drops_drawn = 0.0;
  double substeps = 0.0;          ///< from the start of the prewarm to the last frame of the run
  double drop_steps = 0.0;        ///< drops × substeps: the simulation's work
  double simulation_bytes = 0.0;  ///< raintrace's own peak memory (simulation and export)
  double povray_bytes = 0.0;      ///< one POV-Ray process parsing and tracing one frame
  int povray_processes = 0;       ///< POV-Ray processes in flight (0: export only)
  [[nodiscard]] double total_bytes() const {
    return simulation_bytes + povray_processes * povray_bytes;
  }
};

struct BudgetLimits {
  /// Most drop-steps a run may simulate. Default 1e12: about three hours at the simulation's
  /// ~1e8 drop-steps per second (bench/sim_bench, 2 cores).
  double max_drop_steps = 1e12;
  /// Most memory a run may need, bytes. Default: default_max_memory_bytes().
  double max_memory_bytes = 0.0;
};

/// 4 GiB, or half of this machine's physical memory when that is less.
double default_max_memory_bytes();

/// The budget of simulating frames 1..range.last of `scene` with `povray_processes` POV-Ray
/// processes in flight. Throws std::invalid_argument for simulation parameters World refuses.
Budget estimate_budget(const SceneToExport& scene, FrameSpan range, int povray_processes);

/// A run that asks for more than a limit allows. what() names the keys to change and the option.
class BudgetExceeded : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Throws BudgetExceeded when the budget passes a limit (max_memory_bytes 0 = the default).
void check_budget(const Budget& budget, const BudgetLimits& limits);

/// "1.5G", "512M", "300k", "2000000" (bytes; K, M, G, T are powers of 1024, an optional
/// trailing "B" or "iB" is accepted); nullopt for anything else or a value <= 0.
std::optional<double> parse_byte_size(std::string_view text);

/// "1.5 GB", "512 MB": bytes for messages, powers of 1024.
std::string format_bytes(double bytes);

}  // namespace raintrace::output
