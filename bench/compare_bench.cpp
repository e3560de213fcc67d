// Benchmarks for compare/: metrics of two 1920×1080 frames (target well under 1 s), and a
// 100-frame folder compared with 1 and 2 threads (reading PNGs included).
// Run briefly: build-*/bench/compare_bench --benchmark_min_time=0.2
#include <benchmark/benchmark.h>
#include <fmt/core.h>

#include <cstdint>
#include <filesystem>
#include <string>

#include "compare/compare_run.h"
#include "compare/diff_image.h"
#include "compare/image_io.h"
#include "compare/metrics.h"
#include "compare/ssim.h"

namespace {

namespace fs = std::filesystem;
using raintrace::compare::Image;

Image noisy_frame(int w, int h, std::uint32_t seed) {
  Image img(w, h, 3);
  for (std::size_t i = 0; i < img.pixels.size(); ++i) {
    seed = seed * 1664525u + 1013904223u;
    img.pixels[i] = float((i / 3) % 997) / 997.0f * 0.9f + float(seed >> 24) / 2550.0f;
  }
  return img;
}

void BM_MetricsFullHd(benchmark::State& state) {
  const Image a = noisy_frame(1920, 1080, 1), b = noisy_frame(1920, 1080, 2);
  for (auto _ : state) {
    benchmark::DoNotOptimize(raintrace::compare::compute_metrics(a, b));
  }
}
BENCHMARK(BM_MetricsFullHd)->Unit(benchmark::kMillisecond);

void BM_SsimFullHd(benchmark::State& state) {
  const Image a = noisy_frame(1920, 1080, 1), b = noisy_frame(1920, 1080, 2);
  for (auto _ : state) {
    benchmark::DoNotOptimize(raintrace::compare::ssim(a, b));
  }
}
BENCHMARK(BM_SsimFullHd)->Unit(benchmark::kMillisecond);

void BM_HeatmapFullHd(benchmark::State& state) {
  const Image a = noisy_frame(1920, 1080, 1), b = noisy_frame(1920, 1080, 2);
  for (auto _ : state) {
    benchmark::DoNotOptimize(raintrace::compare::difference_heatmap(a, b));
  }
}
BENCHMARK(BM_HeatmapFullHd)->Unit(benchmark::kMillisecond);

// 8 frames of 640×360 PNG per side, written once.
/// The case: a 100-frame folder, compared frame by frame (PNG reading included).
constexpr int kFolderFrames = 100;

const fs::path& frame_folders() {
  static const fs::path root = [] {
    const fs::path dir = fs::temp_directory_path() / "raintrace_compare_bench_100";
    for (const char* side : {"a", "b"}) {
      fs::create_directories(dir / side);
      for (int i = 0; i < kFolderFrames; ++i) {
        const fs::path file = dir / side / fmt::format("frame_{:04d}.png", i);
        if (!fs::exists(file)) {
          raintrace::compare::write_image(
              file, noisy_frame(640, 360, std::uint32_t(i + (side[0] == 'b'))));
        }
      }
    }
    return dir;
  }();
  return root;
}

void BM_FolderOfFrames(benchmark::State& state) {
  const fs::path& dir = frame_folders();
  raintrace::compare::CompareOptions options;
  options.threads = int(state.range(0));
  for (auto _ : state) {
    benchmark::DoNotOptimize(raintrace::compare::compare_paths(dir / "a", dir / "b", options));
  }
}
BENCHMARK(BM_FolderOfFrames)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
