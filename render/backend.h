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
/// failure after it is recorded.
RunnerCallbacks folder_callbacks(output::FolderState& folder, ProgressReporter& reporter,
                                 RenderSummary& summary,
                                 const std::function<void(const FrameFailure&)>& on_failed);

}  // namespace raintrace::render
