// Progress of a render, shared by the local and the Slurm backend: the counts, and the one place
// that turns them into elapsed time and an ETA for whoever displays them (cli/).
#pragma once

#include <chrono>
#include <functional>

namespace raintrace::render {

struct RenderProgress {
  /// Pictures (images and masks) to render in this run. While frames are still being exported
  /// this counts every frame not yet exported as one to render, and drops as exported frames
  /// turn out to be up to date.
  int total = 0;
  int done = 0;            ///< rendered (and developed) so far in this run, developed_only included
  int developed_only = 0;  ///< frames whose EXR was current: developed without POV-Ray
  int failed = 0;
  int skipped = 0;  ///< frames already up to date before the run
  double elapsed_seconds = 0.0;
  /// Estimated seconds left from the rate so far; negative while unknown.
  double eta_seconds = -1.0;
  int exported = 0;      ///< frames exported so far in this run (while exporting)
  int export_total = 0;  ///< frames this run exports; 0 when rendering an exported folder
};

/// Keeps a RenderProgress and reports it, with elapsed time and ETA, to a callback.
class ProgressReporter {
 public:
  explicit ProgressReporter(std::function<void(const RenderProgress&)> on_progress)
      : m_on_progress{std::move(on_progress)} {}

  RenderProgress& progress() { return m_progress; }
  [[nodiscard]] const RenderProgress& progress() const { return m_progress; }

  /// Updates elapsed time and ETA (from the pace of finished pictures) and calls the callback.
  void report() {
    auto& p = m_progress;
    p.elapsed_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    const int finished = p.done + p.failed;
    p.eta_seconds = finished > 0 ? p.elapsed_seconds / finished * (p.total - finished) : -1.0;
    if (m_on_progress) m_on_progress(p);
  }

 private:
  std::function<void(const RenderProgress&)> m_on_progress;
  std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
  RenderProgress m_progress;
};

}  // namespace raintrace::render
