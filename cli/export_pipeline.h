// Simulate a scene and write its POV-Ray output folder. Shared by `raintrace export` and
// `raintrace render` (which then ray-traces the folder).
#pragma once

#include <atomic>
#include <filesystem>
#include <functional>

#include "cli/scene.h"
#include "povgen/manifest.h"

namespace raintrace::cli {

struct ExportProgress {
  int frames_done = 0;
  int frames_total = 0;
};

/// Simulates frames 1..range.last (earlier frames are simulated but not written: the state
/// depends on all of them) and writes the folder layout of docs/design.md into out_dir:
/// scene.ini, scene.inc, frames/, textures/, manifest.json. Frames whose .pov text is unchanged
/// keep their manifest status, so a re-export does not force re-rendering.
void export_scene(const Scene& scene, const FrameRange& range, const std::filesystem::path& out_dir,
                  const std::function<void(const ExportProgress&)>& on_progress = {});

/// What `raintrace render` needs to ray-trace frames while later ones are still simulated.
struct ExportHooks {
  std::function<void(const ExportProgress&)> on_progress;
  /// Called once the shared files and manifest.json (this run's header; frames of the range
  /// listed without an input_hash until re-exported) are written, before the simulation starts.
  std::function<void()> on_shared_files;
  /// When set, each frame is handed over as soon as its files are at their final names, and
  /// manifest.json is not written again: the receiver records the entries (the renderer owns
  /// the manifest while both run). Unset: manifest.json is written once all frames are.
  std::function<void(povgen::FrameEntry)> on_frame;
  /// Checked between frames: when set, the export ends early (no error).
  const std::atomic<bool>* stop = nullptr;
};

/// export_scene with hooks. The frame files are byte-identical whatever the hooks do.
void export_scene(const Scene& scene, const FrameRange& range, const std::filesystem::path& out_dir,
                  const ExportHooks& hooks);

}  // namespace raintrace::cli
