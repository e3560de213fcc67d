// Simulate a scene and write its POV-Ray output folder. Shared by `raintrace export` and
// `raintrace render` (which then ray-traces the folder).
#pragma once

#include <filesystem>
#include <functional>

#include "cli/scene.h"

namespace raintrace::cli {

struct ExportProgress {
  int frames_done = 0;
  int frames_total = 0;
};

/// Simulates frames 1..range.last (earlier frames are simulated but not written: the state
/// depends on all of them) and writes the folder layout of shared/DESIGN.md into out_dir:
/// scene.ini, scene.inc, frames/, textures/, manifest.json. Frames whose .pov text is unchanged
/// keep their manifest status, so a re-export does not force re-rendering.
void export_scene(const Scene& scene, const FrameRange& range, const std::filesystem::path& out_dir,
                  const std::function<void(const ExportProgress&)>& on_progress = {});

}  // namespace raintrace::cli
