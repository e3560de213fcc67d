// Local backend: planning from the manifest, the runner, and manifest updates per frame.
#include "render/local_render.h"

#include <chrono>
#include <map>
#include <stdexcept>

#include "povgen/manifest.h"
#include "render/frame_plan.h"
#include "render/process.h"

namespace raintrace::render {

void require_povray() {
  if (!find_program("povray")) {
    throw std::runtime_error("POV-Ray not found: install it with `sudo apt-get install povray`");
  }
}

void clean_temp_images(const std::filesystem::path& out_dir) {
  std::filesystem::remove_all(out_dir / temp_dir_name());
}

RenderSummary render_local(const std::filesystem::path& out_dir,
                           const LocalRenderSettings& settings) {
  require_povray();
  const auto manifest_path = out_dir / "manifest.json";
  povgen::Manifest manifest = povgen::read_manifest(manifest_path);
  clean_temp_images(out_dir);
  const int digits = frame_digits(manifest);

  std::map<int, std::size_t> index_of;
  for (std::size_t i = 0; i < manifest.frames.size(); ++i) index_of[manifest.frames[i].number] = i;

  const std::vector<int> frames =
      frames_needing_render(manifest, out_dir, settings.force, settings.only);
  std::vector<int> masks;
  if (settings.mask) {
    for (const auto& f : manifest.frames) {
      if (settings.only && (f.number < settings.only->first || f.number > settings.only->last)) {
        continue;
      }
      const bool stale = std::binary_search(frames.begin(), frames.end(), f.number);
      if (settings.force || stale ||
          !std::filesystem::exists(out_dir / final_image_name(Pass::mask, f.number, digits))) {
        masks.push_back(f.number);
      }
    }
  }

  std::deque<RenderJob> queue;
  const int jobs = std::max(1, settings.jobs);
  for (const auto& span : split_into_spans(frames, jobs, settings.max_span)) {
    queue.push_back({Pass::image, span});
  }
  for (const auto& span : split_into_spans(masks, jobs, settings.max_span)) {
    queue.push_back({Pass::mask, span});
  }

  RenderSummary summary;
  auto& progress = summary.progress;
  progress.total = static_cast<int>(frames.size() + masks.size());
  progress.skipped = static_cast<int>(manifest.frames.size()) - static_cast<int>(frames.size());
  if (settings.only) {
    progress.skipped = 0;
    for (const auto& f : manifest.frames) {
      if (f.number >= settings.only->first && f.number <= settings.only->last) ++progress.skipped;
    }
    progress.skipped -= static_cast<int>(frames.size());
  }
  const auto start = std::chrono::steady_clock::now();
  auto report = [&] {
    progress.elapsed_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const int finished = progress.done + progress.failed;
    progress.eta_seconds =
        finished > 0 ? progress.elapsed_seconds / finished * (progress.total - finished) : -1.0;
    if (settings.on_progress) settings.on_progress(progress);
  };

  RunnerSettings runner;
  runner.jobs = jobs;
  runner.width = manifest.width;
  runner.height = manifest.height;
  runner.digits = digits;
  runner.stop = settings.stop;
  RunnerCallbacks callbacks;
  callbacks.on_rendered = [&](Pass pass, int frame, double seconds) {
    ++progress.done;
    if (pass == Pass::image) {
      auto& entry = manifest.frames[index_of.at(frame)];
      entry.status = "rendered";
      entry.rendered_hash = entry.input_hash;
      entry.render_seconds = seconds;
      entry.error.clear();
      povgen::write_manifest(manifest_path, manifest);
    }
    report();
  };
  callbacks.on_failed = [&](const FrameFailure& failure) {
    ++progress.failed;
    summary.failures.push_back(failure);
    if (failure.pass == Pass::image) {
      auto& entry = manifest.frames[index_of.at(failure.frame)];
      entry.status = "failed";
      entry.rendered_hash.clear();
      entry.error = failure.summary();
      povgen::write_manifest(manifest_path, manifest);
    }
    if (settings.on_failed) settings.on_failed(failure);
    report();
  };
  callbacks.on_tick = report;
  report();
  summary.interrupted = !run_povray_jobs(out_dir, std::move(queue), runner, callbacks);
  report();
  return summary;
}

}  // namespace raintrace::render
