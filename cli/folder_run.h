// What `raintrace export` and `raintrace render` share before they touch an output folder: the
// loaded scene as the exporter takes it, and this process's command line for the folder's lock.
#pragma once

#include <string>

#include "cli/scene.h"
#include "output/budget.h"
#include "output/export.h"

namespace CLI {
class App;
}

namespace raintrace::cli {

/// The --max-memory and --max-drop-steps options as given.
struct LimitArgs {
  std::string max_memory;     ///< "8G"; empty = the default
  double max_drop_steps = 0;  ///< 0 = the default
};

/// Adds --max-memory and --max-drop-steps to a command that simulates (simulate, export, render).
void add_limit_options(CLI::App& command, LimitArgs& limits);

/// Estimates the run (output/budget.h) and throws output::BudgetExceeded past the limits, or
/// std::invalid_argument for a --max-memory that is not a size. Nothing is written before.
void check_run_budget(const output::SceneToExport& scene, output::FrameSpan range,
                      int povray_processes, const LimitArgs& limits);

/// The scene as output::export_frames takes it.
output::SceneToExport scene_to_export(const Scene& scene);

/// Claims `out` for the scene (output::FolderState::claim with the identity of the scene's
/// canonical form, canonical_scene_text) and records how its frames are developed (the
/// [camera] develop keys). `scene` is the scene as changed by command-line options.
output::FolderState claim_folder(const std::filesystem::path& out, const Scene& scene,
                                 const output::SceneToExport& to_export, bool force,
                                 output::ClaimNote* note);

/// One line for the user when files POV-Ray reads were edited in the folder since raintrace
/// wrote them (FolderState::edited_inputs); empty when none were. `exporting`: this run writes
/// the scene's own files over them.
std::string hand_edit_note(const output::FolderState& folder, bool exporting);

/// This process's command line, shell-quoted ("raintrace render a.toml -o out"), for the lock
/// record that tells a second run who holds the folder.
std::string this_command();

}  // namespace raintrace::cli
