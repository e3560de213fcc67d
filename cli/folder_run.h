// What `raintrace export` and `raintrace render` share before they touch an output folder: the
// loaded scene as the exporter takes it, and this process's command line for the folder's lock.
#pragma once

#include <string>

#include "cli/scene.h"
#include "output/export.h"

namespace raintrace::cli {

/// The scene as output::export_frames takes it.
output::SceneToExport scene_to_export(const Scene& scene);

/// This process's command line, shell-quoted ("raintrace render a.toml -o out"), for the lock
/// record that tells a second run who holds the folder.
std::string this_command();

}  // namespace raintrace::cli
