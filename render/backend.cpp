// Runner events → folder transitions and progress.
#include "render/backend.h"

#include <fmt/core.h>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "output/disk_space.h"
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

RunnerCallbacks folder_callbacks(output::FolderState& folder, ProgressReporter& reporter,
                                 RenderSummary& summary,
                                 const std::function<void(const FrameFailure&)>& on_failed,
                                 std::function<void(int frame)> develop) {
  RunnerCallbacks callbacks;
  callbacks.on_started = [&folder, &reporter](const RenderJob& job) {
    folder.rendering(job.pass, job.span);
    reporter.span_started(job.pass, job.span);
  };
  callbacks.on_rendered = [&folder, &reporter, develop](Pass pass, int frame, double seconds) {
    folder.rendered(pass, frame, seconds);
    reporter.picture_traced(pass, frame);
    if (pass == Pass::image) {
      const auto* f = folder.find(frame);
      if (f != nullptr && f->image.status == output::FrameStatus::rendered && develop) {
        develop(frame);
      }
    } else {
      ++reporter.progress().done;
    }
    reporter.report();
  };
  callbacks.on_failed = [&folder, &reporter, &summary, on_failed](const FrameFailure& failure) {
    folder.failed(failure.pass, failure.frame, failure.summary());
    reporter.picture_failed(failure.pass, failure.frame);
    ++reporter.progress().failed;
    summary.failures.push_back(failure);
    if (on_failed) on_failed(failure);
    reporter.report();
  };
  callbacks.on_traced_share = [&reporter](Pass pass, int frame, double share) {
    reporter.picture_share(pass, frame, share);
  };
  callbacks.on_tick = [&reporter] { reporter.report(); };
  return callbacks;
}

}  // namespace raintrace::render

namespace raintrace::render {

void record_developed(output::FolderState& folder, ProgressReporter& reporter,
                      RenderSummary& summary, const std::vector<DevelopResult>& results,
                      const std::function<void(const FrameFailure&)>& on_failed) {
  for (const DevelopResult& r : results) {
    if (r.error.empty()) {
      folder.developed(r.frame, r.seconds);
      ++reporter.progress().done;
      if (r.only) ++reporter.progress().developed_only;
      reporter.report();
      continue;
    }
    folder.develop_failed(r.frame, r.error);
    // As for POV-Ray: a full disk fails every further frame, so it ends the run (exit code 3).
    const auto& id = folder.manifest().identity;
    output::throw_if_out_of_space(
        folder.dir(), static_cast<std::uint64_t>(id.width) * id.height * 3 + 65536,
        fmt::format("could not develop frame {} into {}", r.frame, folder.dir().string()));
    FrameFailure failure;
    failure.frame = r.frame;
    failure.pass = Pass::image;
    failure.in_develop = true;
    failure.error_lines = {r.error};
    ++reporter.progress().failed;
    summary.failures.push_back(failure);
    if (on_failed) on_failed(failure);
    reporter.report();
  }
}

void finish_developing(DevelopQueue& queue, output::FolderState& folder, ProgressReporter& reporter,
                       RenderSummary& summary,
                       const std::function<void(const FrameFailure&)>& on_failed) {
  while (!queue.idle()) {
    record_developed(folder, reporter, summary, queue.take(), on_failed);
    reporter.report();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  record_developed(folder, reporter, summary, queue.take(), on_failed);
}

}  // namespace raintrace::render
