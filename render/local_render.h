// Renders an exported output folder on this machine: reads manifest.json, renders the frames
// that are missing or stale, and records each result in manifest.json as it lands, so an
// interrupted run resumes where it stopped.
#pragma once

#include <atomic>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "render/frame_feed.h"
#include "render/povray_runner.h"

namespace raintrace::render {

struct RenderProgress {
  /// Frames (and masks) to render in this run. While frames are still being exported this
  /// counts every frame not yet exported as one to render, and drops as exported frames turn
  /// out to be up to date.
  int total = 0;
  int done = 0;  ///< rendered so far in this run
  int failed = 0;
  int skipped = 0;  ///< already up to date before the run
  double elapsed_seconds = 0.0;
  /// Estimated seconds left from the rate so far; negative while unknown.
  double eta_seconds = -1.0;
  int exported = 0;      ///< frames exported so far in this run (with a FrameFeed)
  int export_total = 0;  ///< frames this run exports; 0 when rendering an exported folder
};

struct LocalRenderSettings {
  int jobs = 2;        ///< POV-Ray processes in flight, >= 1
  int max_span = 12;   ///< most frames one POV-Ray process renders
  bool force = false;  ///< re-render frames that are up to date
  bool mask = false;   ///< also render images/mask_NNNN.png (mask.ini, from export --mask)
  std::optional<FrameSpan> only;  ///< restrict to these frames
  /// Frames still being exported (`raintrace render SCENE.toml`): when set, the frames of the
  /// run come only from here, each rendered as soon as it and the rest of its span exist,
  /// while later frames are simulated. manifest.json must already hold this run's header.
  FrameFeed* incoming = nullptr;
  const std::atomic<bool>* stop = nullptr;
  std::function<void(const RenderProgress&)> on_progress;  ///< ~10×/s and on every frame
  std::function<void(const FrameFailure&)> on_failed;
  /// One line about something that went wrong without failing a frame: "environment plate
  /// failed (…): frames render the full environment".
  std::function<void(const std::string&)> on_notice;
};

struct RenderSummary {
  RenderProgress progress;
  std::vector<FrameFailure> failures;
  bool interrupted = false;
};

/// A folder with plate.ini gets its environment plate (environment_plate.h) brought up to date
/// before any frame's POV-Ray starts: without settings.incoming only when some frame or mask is
/// to be rendered; with it, from the start, while the exporter works. A failed plate is reported
/// through on_notice and the frames render the full environment.
/// Throws std::runtime_error when POV-Ray is not installed (one line, with the apt command) or
/// the folder has no readable manifest.json. With settings.incoming, returns once the feed is
/// closed and everything it brought is rendered, or when stopped (then after the feed closes, so
/// manifest.json lists every frame the exporter finished).
RenderSummary render_local(const std::filesystem::path& out_dir,
                           const LocalRenderSettings& settings);

/// Throws the "POV-Ray not found" error unless `povray` is in PATH.
void require_povray();

/// Removes images/.tmp: whatever is there was left by a killed run and is
/// never trusted.
void clean_temp_images(const std::filesystem::path& out_dir);

}  // namespace raintrace::render
