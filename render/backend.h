// What the local and the Slurm backend share: the settings every run has (which frames, how to
// stop, whom to tell), the summary they return, and the one place that turns POV-Ray's results
// into the folder's transitions and the progress counts. Each backend only adds how it runs
// POV-Ray.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <vector>

#include "output/folder_state.h"
#include "render/develop_queue.h"
#include "render/povray_runner.h"
#include "render/progress.h"

namespace raintrace::render {

struct BackendSettings {
  bool force = false;             ///< render frames that are up to date again
  std::optional<FrameSpan> only;  ///< restrict to these frames
  /// Set from a signal handler: POV-Ray is stopped (the Slurm job cancelled), finished frames
  /// are kept.
  const std::atomic<bool>* stop = nullptr;
  std::function<void(const RenderProgress&)> on_progress;  ///< ~10×/s and on every frame
  std::function<void(const FrameFailure&)> on_failed;
  /// What this run renders and why (not while frames arrive from an exporter: they are
  /// decided one by one as they come).
  std::function<void(const output::RenderPlan&)> on_plan;
};

struct RenderSummary {
  RenderProgress progress;
  std::vector<FrameFailure> failures;
  bool interrupted = false;
};

/// Throws the "POV-Ray not found" error (one line, with the apt command) unless `povray` is in
/// PATH.
void require_povray();

/// Removes images/.tmp: whatever is there was left by a killed run and is never trusted.
void clean_temp_images(const std::filesystem::path& out_dir);

/// Runner callbacks that record each event in the folder (rendering, rendered, failed) and in
/// the progress: shared by the local backend and the Slurm merge. `on_failed` is told of every
/// failure after it is recorded. `develop` is called with each frame whose EXR was just
/// recorded as rendered: the frame counts as done once its PNG is developed
/// (record_developed), a mask as soon as it is rendered.
RunnerCallbacks folder_callbacks(output::FolderState& folder, ProgressReporter& reporter,
                                 RenderSummary& summary,
                                 const std::function<void(const FrameFailure&)>& on_failed,
                                 std::function<void(int frame)> develop);

/// Records develop results in the folder (developed, or develop_failed) and in the progress
/// (done, or failed with a FrameFailure in the summary, told to on_failed). Throws
/// std::system_error (ENOSPC) when a develop failed because the folder's disk is full.
void record_developed(output::FolderState& folder, ProgressReporter& reporter,
                      RenderSummary& summary, const std::vector<DevelopResult>& results,
                      const std::function<void(const FrameFailure&)>& on_failed);

/// Waits (reporting progress) until `queue` has developed everything submitted, or a stop
/// request ends it, recording every result.
void finish_developing(DevelopQueue& queue, output::FolderState& folder, ProgressReporter& reporter,
                       RenderSummary& summary,
                       const std::function<void(const FrameFailure&)>& on_failed);

}  // namespace raintrace::render
