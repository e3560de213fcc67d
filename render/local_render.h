// Local backend: renders what the output folder's state says is due (output::FolderState::plan,
// or frames as the exporter publishes them) with POV-Ray processes on this machine, and hands
// every result back to the state, which records it in manifest.json as it lands: an interrupted
// run resumes where it stopped.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "output/folder_state.h"
#include "render/frame_feed.h"
#include "render/povray_runner.h"
#include "render/progress.h"

namespace raintrace::render {

struct LocalRenderSettings {
  int jobs = 2;                   ///< POV-Ray processes in flight, >= 1
  int max_span = 12;              ///< most frames one POV-Ray process renders
  bool force = false;             ///< re-render frames that are up to date
  std::optional<FrameSpan> only;  ///< restrict to these frames
  /// Frames still being exported (`raintrace render SCENE.toml`): when set, the frames of the
  /// run come only from here, each rendered as soon as it and the rest of its span exist,
  /// while later frames are simulated. The folder must already know this export's range
  /// (output::FolderState::begin_export).
  FrameFeed* incoming = nullptr;
  const std::atomic<bool>* stop = nullptr;
  std::function<void(const RenderProgress&)> on_progress;  ///< ~10×/s and on every frame
  std::function<void(const FrameFailure&)> on_failed;
  /// One line about something that went wrong without failing a frame: "environment plate
  /// failed (…): frames render the full environment".
  std::function<void(const std::string&)> on_notice;
  /// What this run renders and why (not while frames arrive from an exporter: they are
  /// decided one by one as they come).
  std::function<void(const output::RenderPlan&)> on_plan;
};

struct RenderSummary {
  RenderProgress progress;
  std::vector<FrameFailure> failures;
  bool interrupted = false;
};

/// Renders the folder's frames (and masks, for a folder exported with them) that are not up to
/// date. A folder with plate.ini gets its environment plate (environment_plate.h) brought up to
/// date before any frame's POV-Ray starts: without settings.incoming only when something is to
/// be rendered; with it, from the start, while the exporter works. A failed plate is reported
/// through on_notice and the frames render the full environment.
/// Throws std::runtime_error when POV-Ray is not installed (one line, with the apt command).
/// With settings.incoming, returns once the feed is closed and everything it brought is
/// rendered, or when stopped (then after the feed closes, so the manifest records every frame
/// the exporter finished).
RenderSummary render_local(output::FolderState& folder, const LocalRenderSettings& settings);

/// Throws the "POV-Ray not found" error unless `povray` is in PATH.
void require_povray();

/// Removes images/.tmp: whatever is there was left by a killed run and is never trusted.
void clean_temp_images(const std::filesystem::path& out_dir);

/// The runner callbacks that turn the runner's events into the folder's transitions
/// (rendering, rendered, failed) and the progress counts; shared by the local backend and the
/// Slurm merge. `on_failed` is told of every failure after it is recorded.
RunnerCallbacks folder_callbacks(output::FolderState& folder, ProgressReporter& reporter,
                                 RenderSummary& summary,
                                 const std::function<void(const FrameFailure&)>& on_failed);

}  // namespace raintrace::render
