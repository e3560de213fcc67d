// Runner events → folder transitions and progress.
#include "render/backend.h"

#include <stdexcept>

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
                                 const std::function<void(const FrameFailure&)>& on_failed) {
  RunnerCallbacks callbacks;
  callbacks.on_started = [&folder](const RenderJob& job) { folder.rendering(job.pass, job.span); };
  callbacks.on_rendered = [&folder, &reporter](Pass pass, int frame, double seconds) {
    folder.rendered(pass, frame, seconds);
    ++reporter.progress().done;
    reporter.report();
  };
  callbacks.on_failed = [&folder, &reporter, &summary, on_failed](const FrameFailure& failure) {
    folder.failed(failure.pass, failure.frame, failure.summary());
    ++reporter.progress().failed;
    summary.failures.push_back(failure);
    if (on_failed) on_failed(failure);
    reporter.report();
  };
  callbacks.on_tick = [&reporter] { reporter.report(); };
  return callbacks;
}

}  // namespace raintrace::render
