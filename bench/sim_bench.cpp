// sim_bench: World substeps at 10 k … 10 M drops; counter drop_steps (per second).
// Args: drops, threads (0 = all cores), merging (0/1). Keep runs short on a shared machine:
//   sim_bench --benchmark_min_time=0.1 --benchmark_filter='drops:(10000|100000|1000000)/'
#include <benchmark/benchmark.h>

#include <cmath>

#include "sim/drop_size.h"
#include "sim/spawn_region.h"
#include "sim/terminal_velocity.h"
#include "sim/view_volume.h"
#include "sim/world.h"

namespace {
using namespace raintrace::sim;

// Default scene with far_m chosen so that the simulated box holds about `drops` drops
// (the box volume grows as far³, so bisect on far_m).
SimParams scene_with(double drops, int threads, bool merging) {
  SimParams p;
  p.rain.rate_mm_per_h = 25.0;
  p.rain.merging = merging;
  p.prewarm_s = 0.0;
  p.threads = threads;
  const DropSizeModel sizes(p.rain);
  double lo = p.rain.near_m * 1.01, hi = 1000.0;
  for (int k = 0; k < 60; ++k) {
    const double far = 0.5 * (lo + hi);
    const ViewVolume view(p.camera, p.rain.near_m, far);
    const SpawnRegion region(view, p.ground_y_m, p.rain.ceiling_margin_m, {}, 0.0,
                             terminal_velocity(p.rain.diameter_min_mm * 1e-3));
    (sizes.number_density_per_m3() * region.volume_m3() < drops ? lo : hi) = far;
  }
  p.rain.far_m = lo;
  return p;
}

void BM_WorldStep(benchmark::State& state) {
  const SimParams p = scene_with(static_cast<double>(state.range(0)),
                                 static_cast<int>(state.range(1)), state.range(2) != 0);
  World world(p);
  // One iteration = 20 substeps (40 ms), the merging period, so merging cost is averaged in.
  double drop_steps = 0.0;
  for (auto _ : state) {
    for (int k = 0; k < 20; ++k) {
      drop_steps += static_cast<double>(world.drops().size());
      world.step();
    }
  }
  state.counters["drops"] = static_cast<double>(world.drops().size());
  state.counters["drop_steps"] = benchmark::Counter(drop_steps, benchmark::Counter::kIsRate);
}

BENCHMARK(BM_WorldStep)
    ->ArgNames({"drops", "threads", "merging"})
    ->ArgsProduct({{10'000, 100'000, 1'000'000, 10'000'000}, {1, 2}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
