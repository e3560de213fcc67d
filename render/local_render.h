// Local backend: renders what the output folder's state says is due (output::FolderState::plan,
// or frames as the exporter publishes them) with POV-Ray processes on this machine, and hands
// every result back to the state, which records it in manifest.json as it lands: an interrupted
// run resumes where it stopped.
#pragma once

#include <string>

#include "render/backend.h"
#include "render/frame_feed.h"

namespace raintrace::render {

struct LocalRenderSettings : BackendSettings {
  int jobs = 2;       ///< POV-Ray processes in flight, >= 1
  int max_span = 12;  ///< most frames one POV-Ray process renders
  /// Frames still being exported (`raintrace render SCENE.toml`): when set, the frames of the
  /// run come only from here, each rendered as soon as it and the rest of its span exist,
  /// while later frames are simulated. The folder must already know this export's range
  /// (output::FolderState::begin_export).
  FrameFeed* incoming = nullptr;
  /// One line about something that went wrong without failing a frame: "environment plate
  /// failed (…): frames render the full environment".
  std::function<void(const std::string&)> on_notice;
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

}  // namespace raintrace::render
