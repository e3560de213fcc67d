// povgen throughput: drops turned into POV-Ray text per second at 10 k, 100 k and 1 M drops
// per frame: values alone on one thread (BM_FrameValues) and on 1 and 2
// (BM_FrameValuesThreads), text alone with 1 and 2 writer threads, and both together
// (BM_DropsWritten). Synthetic rain fills the default camera's view to 12 m. What the text
// costs against POV-Ray's parse of it is bench/export_vs_parse.cpp's question.
#include <benchmark/benchmark.h>

#include "povgen/export_params.h"
#include "povgen/frame_text.h"
#include "povgen/frame_values.h"
#include "povgen/test_support/synthetic_rain.h"

namespace {

using namespace raintrace;

const sim::Frame& rain(std::size_t count) {
  static std::size_t cached_count = 0;
  static sim::Frame cached;
  if (cached_count != count) {
    cached = povgen::test_support::synthetic_rain(count, povgen::ExportParams{}.camera, 16.0 / 9.0,
                                                  12.0, 1.5);
    cached_count = count;
  }
  return cached;
}

/// Every drop written: the text-writing workload stays the same whatever the level-of-detail
/// default (min_streak_coverage thins faint streaks, see export_params.h).
povgen::ExportParams every_streak() {
  povgen::ExportParams look;
  look.min_streak_coverage = 0.0;
  return look;
}

// Each benchmark runs its work once untimed before the loop (the warm-ups below): at 1 M drops
// --benchmark_min_time=0.2 times one or two iterations, and the first would pay for faulting
// in fresh pages of the reused FrameValues and buffers, which export_scene pays only for its
// first frame.

void BM_FrameValues(benchmark::State& state) {
  const sim::Frame& frame = rain(static_cast<std::size_t>(state.range(0)));
  const povgen::ExportParams look = every_streak();
  povgen::FrameValues values;                       // reused across frames, as export_scene does
  povgen::build_frame_values(frame, look, values);  // warm-up
  for (auto _ : state) {
    povgen::build_frame_values(frame, look, values);
    benchmark::DoNotOptimize(values.streaks.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

/// Values alone on 1 and 2 threads (chunks of drops in parallel).
void BM_FrameValuesThreads(benchmark::State& state) {
  const sim::Frame& frame = rain(static_cast<std::size_t>(state.range(0)));
  const povgen::ExportParams look = every_streak();
  const int threads = static_cast<int>(state.range(1));
  povgen::FrameValues values;
  povgen::build_frame_values(frame, look, values, {}, threads);  // warm-up
  for (auto _ : state) {
    povgen::build_frame_values(frame, look, values, {}, threads);
    benchmark::DoNotOptimize(values.streaks.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_FrameText(benchmark::State& state) {
  const sim::Frame& frame = rain(static_cast<std::size_t>(state.range(0)));
  const povgen::FrameValues values = povgen::build_frame_values(frame, every_streak());
  const int threads = static_cast<int>(state.range(1));
  std::size_t bytes = 0;
  // The sink counts bytes as a file write would receive them (export_scene streams to a file).
  const povgen::TextSink sink = [&bytes](std::string_view piece) { bytes += piece.size(); };
  povgen::write_frame_text(values, sink, {}, threads);  // warm-up
  for (auto _ : state) {
    bytes = 0;
    povgen::write_frame_text(values, sink, {}, threads);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(bytes));
}

/// The whole pure path of one frame: values then text, both on `threads` threads, as
/// export_scene runs it.
void BM_DropsWritten(benchmark::State& state) {
  const sim::Frame& frame = rain(static_cast<std::size_t>(state.range(0)));
  const povgen::ExportParams look = every_streak();
  const int threads = static_cast<int>(state.range(1));
  povgen::FrameValues values;
  std::size_t bytes = 0;
  const povgen::TextSink sink = [&bytes](std::string_view piece) { bytes += piece.size(); };
  povgen::build_frame_values(frame, look, values, {}, threads);  // warm-up
  povgen::write_frame_text(values, sink, {}, threads);
  for (auto _ : state) {
    povgen::build_frame_values(frame, look, values, {}, threads);
    povgen::write_frame_text(values, sink, {}, threads);
  }
  benchmark::DoNotOptimize(bytes);
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

BENCHMARK(BM_FrameValues)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FrameValuesThreads)
    ->ArgsProduct({{10'000, 100'000, 1'000'000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_FrameText)
    ->ArgsProduct({{10'000, 100'000, 1'000'000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_DropsWritten)
    ->ArgsProduct({{10'000, 100'000, 1'000'000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
