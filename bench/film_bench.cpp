// Benchmarks for film/: the cost of developing one frame at the Table 1 preview size (320×240),
// the default example's 640×360 and the final 1280×720 — each step alone, the whole develop in
// memory, and develop_file with the EXR read and the PNG write. OpenImageIO's own threads are
// limited to one (as a render with several frames in flight would), so the figures are CPU time
// per frame on one core.
// Run briefly: build/bench/film_bench --benchmark_min_time=0.2
#include <benchmark/benchmark.h>

#include <OpenImageIO/imageio.h>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "film/bloom.h"
#include "film/develop.h"
#include "film/diffraction_spikes.h"
#include "film/display_transform.h"
#include "film/grain.h"
#include "film/image_file.h"
#include "film/sensor_noise.h"
#include "film/softness.h"
#include "film/vignette.h"

namespace {

namespace fs = std::filesystem;
using raintrace::film::RgbImage;

/// A night frame in scene-linear light: a dim ramp with a row of lamps 50–500× brighter.
RgbImage night_frame(int w, int h) {
  RgbImage image(w, h);
  std::uint32_t state = 12345u;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      state = state * 1664525u + 1013904223u;
      const float base = 0.005f + 0.05f * float(y) / float(h) + float(state >> 24) / 25500.0f;
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = base * (1.0f + 0.1f * float(c));
    }
  }
  for (int lamp = 1; lamp < 8; ++lamp) {
    const int cx = lamp * w / 8, cy = h / 4;
    for (int y = cy - 2; y <= cy + 2; ++y)
      for (int x = cx - 3; x <= cx + 3; ++x)
        for (int c = 0; c < 3; ++c) image.at(x, y, c) = 50.0f * float(lamp);
  }
  return image;
}

const raintrace::film::DisplayTransform& filmic() {
  static const raintrace::film::DisplayTransform transform;
  return transform;
}

void sizes(benchmark::internal::Benchmark* b) {
  b->Args({320, 240})->Args({640, 360})->Args({1280, 720})->Unit(benchmark::kMillisecond);
}

void one_oiio_thread() { OIIO::attribute("threads", 1); }

void BM_Bloom(benchmark::State& state) {
  const RgbImage frame = night_frame(int(state.range(0)), int(state.range(1)));
  for (auto _ : state) benchmark::DoNotOptimize(raintrace::film::bloom(frame, 0.04));
}
BENCHMARK(BM_Bloom)->Apply(sizes);

void filmic_display(benchmark::State& state, raintrace::film::Look look) {
  one_oiio_thread();
  const RgbImage frame = night_frame(int(state.range(0)), int(state.range(1)));
  for (auto _ : state) {
    benchmark::DoNotOptimize(filmic().to_display(frame, raintrace::film::View::filmic, look));
  }
}

/// The default look: a look transform, then the Filmic view.
void BM_FilmicDisplay(benchmark::State& state) {
  filmic_display(state, raintrace::film::Look::medium_high_contrast);
}
BENCHMARK(BM_FilmicDisplay)->Apply(sizes);

/// Filmic's own curve: no look transform before the view (half the OpenColorIO work).
void BM_FilmicDisplayBaseCurve(benchmark::State& state) {
  filmic_display(state, raintrace::film::Look::medium_contrast);
}
BENCHMARK(BM_FilmicDisplayBaseCurve)->Apply(sizes);

void BM_VignetteAndGrain(benchmark::State& state) {
  RgbImage frame = night_frame(int(state.range(0)), int(state.range(1)));
  std::int64_t n = 0;
  for (auto _ : state) {
    raintrace::film::apply_vignette(frame, 0.5, 60.0);
    raintrace::film::apply_grain(frame, 0.02, 1, ++n);
  }
}
BENCHMARK(BM_VignetteAndGrain)->Apply(sizes);

/// Three channels of clumped noise where grain draws one: the dearer of the two noises.
void BM_SensorNoise(benchmark::State& state) {
  RgbImage frame = night_frame(int(state.range(0)), int(state.range(1)));
  std::int64_t n = 0;
  for (auto _ : state) raintrace::film::apply_sensor_noise(frame, 0.1, 1, ++n);
}
BENCHMARK(BM_SensorNoise)->Apply(sizes);

/// The lens's softness at the default example's 1 (σ = 0.67 px at 1280): two 5-tap passes.
void BM_Softness(benchmark::State& state) {
  RgbImage frame = night_frame(int(state.range(0)), int(state.range(1)));
  for (auto _ : state) raintrace::film::apply_softness(frame, 1.0);
}
BENCHMARK(BM_Softness)->Apply(sizes);

/// The iris's diffraction spikes, six blades, at the default example's 8 mm opening and at 2 mm
/// (f/20 on a 40 mm lens: four times longer rays), 50° wide: the frame's seven lamps, 35 pixels
/// at 50–350, are its only pixels above 1.
void BM_DiffractionSpikes(benchmark::State& state) {
  const RgbImage frame = night_frame(int(state.range(0)), int(state.range(1)));
  const raintrace::film::Aperture iris{6, double(state.range(2)) / 1000.0};
  for (auto _ : state) {
    RgbImage image = frame;
    raintrace::film::apply_diffraction_spikes(image, iris, 50.0);
    benchmark::DoNotOptimize(image.pixels.data());
  }
}
BENCHMARK(BM_DiffractionSpikes)
    ->Args({1280, 720, 8})
    ->Args({1280, 720, 2})
    ->Unit(benchmark::kMillisecond);

/// The same on a rendered frame, RAINTRACE_BENCH_EXR (skipped without): the whole develop of the
/// default example's look without spikes (range 0) and with six blades at its 8 mm opening
/// (range 8), so the spikes' share of develop is measured on the lights a street really has.
void BM_DevelopRenderedFrame(benchmark::State& state) {
  one_oiio_thread();
  const char* path = std::getenv("RAINTRACE_BENCH_EXR");
  if (path == nullptr) {
    state.SkipWithError("set RAINTRACE_BENCH_EXR to a rendered frame");
    return;
  }
  const RgbImage frame = raintrace::film::read_rgb_image(path);
  const raintrace::film::DevelopSettings settings{.bloom = 0.1,
                                                  .softness = 1,
                                                  .grain = 0,
                                                  .sensor_noise = 0.1,
                                                  .vignette = 0.5,
                                                  .aperture_blades = state.range(0) > 0 ? 6 : 0};
  const raintrace::film::FrameContext context{
      .fov_deg = 50, .seed = 1, .frame = 16, .aperture_m = double(state.range(0)) / 1000.0};
  const raintrace::film::DisplayTransform& display = filmic();  // loaded before the clock runs
  for (auto _ : state) {
    benchmark::DoNotOptimize(raintrace::film::develop(frame, settings, context, display));
  }
}
BENCHMARK(BM_DevelopRenderedFrame)->Arg(0)->Arg(8)->Arg(2)->Unit(benchmark::kMillisecond);

void BM_Develop(benchmark::State& state) {
  one_oiio_thread();
  const RgbImage frame = night_frame(int(state.range(0)), int(state.range(1)));
  const raintrace::film::DevelopSettings settings{.grain = 0.02, .vignette = 0.5};
  for (auto _ : state) {
    benchmark::DoNotOptimize(raintrace::film::develop(frame, settings, {}, filmic()));
  }
}
BENCHMARK(BM_Develop)->Apply(sizes);

/// develop_file on a half-float EXR like POV-Ray's +FE output.
void BM_DevelopFile(benchmark::State& state) {
  one_oiio_thread();
  const int w = int(state.range(0)), h = int(state.range(1));
  const fs::path dir = fs::temp_directory_path() / ("raintrace_film_bench_" + std::to_string(w));
  fs::create_directories(dir);
  const fs::path exr = dir / "frame.exr";
  {
    const RgbImage frame = night_frame(w, h);
    auto out = OIIO::ImageOutput::create(exr.string());
    OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::HALF);
    out->open(exr.string(), spec);
    out->write_image(OIIO::TypeDesc::FLOAT, frame.pixels.data());
    out->close();
  }
  const raintrace::film::DevelopSettings settings{.grain = 0.02, .vignette = 0.5};
  for (auto _ : state) {
    raintrace::film::develop_file(exr, dir / "frame.png", settings, {}, filmic());
  }
  fs::remove_all(dir);
}
BENCHMARK(BM_DevelopFile)->Apply(sizes);

/// Loading Blender's configuration (once per render).
void BM_LoadFilmicConfig(benchmark::State& state) {
  for (auto _ : state) {
    const raintrace::film::DisplayTransform transform;
    benchmark::DoNotOptimize(&transform);
  }
}
BENCHMARK(BM_LoadFilmicConfig)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
