// What a run will ask of the machine, known before anything starts: the simulation's work
// (drops × substeps) and the memory of raintrace and of the POV-Ray processes in flight. A run
// past a limit stops before it creates a file, with a message naming the scene keys to change
// and the option that raises the limit (--max-drop-steps, --max-memory).
//
// The memory model is measured, not derived (Debian 12, 2 cores; BENCHMARKS.md): raintrace's
// peak RSS while exporting was 266 / 418 / 644 MB for 1.1 / 2.2 / 3.9 million simulated drops
// (rate_mm_per_h = 500, far_m = 6 / 8 / 10), i.e. ~115 MB + 136 bytes per drop; POV-Ray's peak
// was 46 / 88 / 141 MB for 0.27 / 0.65 / 1.05 million drops in view at the default streak level
// of detail (~110–150 bytes per drop in view), and 163 MB for 0.27 million with every streak
// kept (min_streak_coverage = 0: ~550 bytes). The estimate rounds these up: 160 bytes at the
// preview's streak threshold, in inverse proportion to a lower one (final's keeps 3.3 times as
// many far streaks), 600 with every streak kept.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "output/export.h"

namespace raintrace::output {

struct Budget {
  double drops = 0.0;             ///< simulated drops at steady state
  double drops_in_view = 0.0;     ///< of those, in the view frustum (what a frame writes)
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
