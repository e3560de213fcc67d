// Simulate a scene and write its frames into an output folder: the thin orchestration over
// sim::World and povgen's three parts (values, text, files), recording each frame in the
// folder's state. Shared by `raintrace export` and `raintrace render`.
#pragma once

#include <atomic>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

#include "output/folder_state.h"
#include "povgen/export_params.h"
#include "sim/params.h"

namespace raintrace::output {

/// A loaded scene, as far as exporting it goes (cli::Scene carries these).
struct SceneToExport {
  sim::SimParams sim;
  povgen::ExportParams look;
  int frames = 1;                   ///< the scene's frame count, >= 1
  std::filesystem::path scene_dir;  ///< resolves [environment] include
};

/// What a folder made from this scene is: the hash of the scene's canonical text (cli's
/// canonical_scene_text: every key that shapes the rendered frames, as loaded), and the settings
/// a command line can change (seed, size, fps, quality, masks) as they will be written.
FolderIdentity identity_of(std::string_view canonical_scene, const SceneToExport& scene);

struct ExportProgress {
  int frames_done = 0;
  int frames_total = 0;
};

/// A frame whose files are complete at their final names.
struct ExportedFrame {
  int number = 0;
  std::string input_hash;  ///< hash of everything POV-Ray reads for it
};

struct ExportHooks {
  std::function<void(const ExportProgress&)> on_progress;
  /// Called once the shared files are written and the folder knows this export's range
  /// (FolderState::begin_export, saved), before the simulation starts.
  std::function<void()> on_shared_files;
  /// When set, each frame is handed over here as soon as its files are complete, and the
  /// export does not touch `folder` after on_shared_files: the receiver applies the frames
  /// (FolderState::frame_exported) on its own thread. Unset: the export records each frame
  /// itself and saves the manifest when it ends, interrupted or not.
  std::function<void(ExportedFrame)> on_frame;
  /// Checked between substeps and frames: once set, the export stops within a substep and
  /// returns false (no error).
  const std::atomic<bool>* stop = nullptr;
};

/// Simulates frames 1..range.last (earlier frames are simulated but not written: the state
/// depends on all of them) and writes the shared files and frames range.first..range.last into
/// folder.dir(). Returns false when stopped early. Throws std::invalid_argument for a range
/// outside 1..scene.frames, std::system_error when a file cannot be written (with the reason).
/// The frame files are byte-identical whatever the hooks do.
bool export_frames(FolderState& folder, const SceneToExport& scene, FrameSpan range,
                   const ExportHooks& hooks = {});

}  // namespace raintrace::output
