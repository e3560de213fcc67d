// Progress of a render, shared by the local and the Slurm backend: the counts, and the one place
// that turns them into elapsed time and an ETA for whoever displays them (cli/). Both follow
// the pace of their POV-Ray processes: the local runner's, and the Slurm tasks' as they publish
// them (slurm_flight.h).
#pragma once

#include <chrono>
#include <functional>
#include <optional>

#include "render/render_pace.h"

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
  /// Estimated seconds left: from the POV-Ray processes' pace where the reporter follows it
  /// (ProgressReporter::follow_pace), else from the rate of finished pictures; negative while
  /// unknown.
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

  /// From now on the ETA follows the pace of the POV-Ray processes (render_pace.h), as the
  /// span_started and picture_… calls tell it; otherwise it is the rate of finished pictures.
  void follow_pace() { m_pace.emplace(Clock::now()); }
  void span_started(Pass pass, const FrameSpan& span) {
    if (m_pace) m_pace->started(pass, span, Clock::now());
  }
  void picture_traced(Pass pass, int frame) {
    if (m_pace) m_pace->finished(pass, frame, Clock::now());
  }
  void picture_failed(Pass pass, int frame) {
    if (m_pace) m_pace->failed(pass, frame, Clock::now());
  }
  /// POV-Ray has traced `share` of the picture's pixels (RenderPace::traced).
  void picture_share(Pass pass, int frame, double share) {
    if (m_pace) m_pace->traced(pass, frame, share, Clock::now());
  }

  /// Updates elapsed time and ETA and calls the callback.
  void report();

 private:
  using Clock = std::chrono::steady_clock;
  std::function<void(const RenderProgress&)> m_on_progress;
  Clock::time_point m_start = Clock::now();
  std::optional<RenderPace> m_pace;
  RenderProgress m_progress;
};

}  // namespace raintrace::render
