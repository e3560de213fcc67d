// `raintrace export SCENE.toml -o OUT [--frames A-B] [--seed N] [--force]`: simulate a scene and
// write its POV-Ray output folder (scene.ini, scene.inc, frames/, textures/, manifest.json),
// which plain `povray scene.ini` renders from inside the folder.
#include <fmt/core.h>
#include <unistd.h>
#include <CLI/CLI.hpp>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "cli/command.h"
#include "cli/exit_codes.h"
#include "cli/folder_run.h"
#include "cli/options.h"
#include "cli/scene.h"
#include "cli/stop_signals.h"
#include "output/export.h"
#include "output/folder_state.h"

namespace raintrace::cli {
namespace {

struct ExportArgs {
  std::string scene;
  std::string out;
  std::string frames;
  std::optional<std::uint64_t> seed;
  bool force = false;
  LimitArgs limits;
};

int run_export(const ExportArgs& args) {
  Scene scene = load_scene_file(args.scene);
  if (args.seed) scene.sim.seed = *args.seed;
  const FrameRange range = parse_frame_range(args.frames, scene.frames);
  const output::SceneToExport to_export = scene_to_export(scene);
  check_run_budget(to_export, {range.first, range.last}, 0, args.limits);
  StopSignals signals;
  output::ClaimNote note;
  auto folder = claim_folder(args.out, scene, to_export, args.force, &note);
  if (!note.text.empty()) fmt::print(stderr, "export: {}\n", note.text);
  if (const auto edits = hand_edit_note(folder, true); !edits.empty()) {
    fmt::print(stderr, "export: {}\n", edits);
  }
  const bool terminal = isatty(fileno(stderr)) != 0;
  fmt::print(stderr, "export: {} frames {}-{} of {} to {}\n", args.scene, range.first, range.last,
             scene.frames, args.out);
  int last_reported = 0;
  output::ExportHooks hooks;
  hooks.stop = &stop_requested();
  hooks.on_progress = [&](const output::ExportProgress& p) {
    if (terminal) {
      fmt::print(stderr, "\rexport: frame {}/{}", p.frames_done, p.frames_total);
      if (p.frames_done == p.frames_total) fmt::print(stderr, "\n");
    } else if (p.frames_done == p.frames_total ||
               p.frames_done * 10 / p.frames_total > last_reported) {
      // Plain lines in logs: one per tenth of the work.
      last_reported = p.frames_done * 10 / p.frames_total;
      fmt::print(stderr, "export: frame {}/{}\n", p.frames_done, p.frames_total);
    }
  };
  if (!output::export_frames(folder, to_export, {range.first, range.last}, hooks)) {
    fmt::print(stderr,
               "{}raintrace: interrupted by {}: frames written so far are kept; run the same "
               "command again to finish\n",
               terminal ? "\n" : "", stop_signal_name());
    return interrupted_exit_code();
  }
  fmt::print(stderr, "export: done; render with `cd {} && povray scene.ini`\n", args.out);
  return exit_code::ok;
}

}  // namespace

Command register_export_command(CLI::App& app) {
  auto args = std::make_shared<ExportArgs>();
  auto* sub = app.add_subcommand(
      "export", "Simulate a scene and write POV-Ray files (scene.ini renders them)");
  sub->footer(
      "Example:\n"
      "  raintrace export examples/night_street.toml -o out/night --frames 1-12\n"
      "  cd out/night && povray scene.ini        # plain POV-Ray renders images/frame_NNNN.exr\n"
      "  raintrace render out/night              # develops them into images/frame_NNNN.png\n"
      "\n"
      "OUT must be new, empty, or a folder raintrace made from the same scene and settings\n"
      "(seed, size, quality, masks); --force replaces what another scene left there.\n"
      "Ctrl-C stops within a second and keeps the frames written so far.\n"
      "A scene asking for more memory or simulation than --max-memory/--max-drop-steps allow\n"
      "stops before anything is written, naming the scene keys to change.\n"
      "Exit codes: 0 done, 2 bad scene file, option or output folder, 3 system error (disk\n"
      "full, permission denied), 4 output folder in use by another raintrace, 130/143 "
      "interrupted.");
  sub->add_option("scene", args->scene, "Scene file (.toml)")->required();
  sub->add_option("-o,--output", args->out, "Output folder (created if missing)")->required();
  sub->add_option("--frames", args->frames, "Frames to write: A-B or N (default: all)");
  add_seed_option(*sub, args->seed);
  sub->add_flag("--force", args->force,
                "Replace a folder made from another scene or with other settings (its frames "
                "and images are deleted), or write into a non-empty folder raintrace did not make");
  add_limit_options(*sub, args->limits);
  return {sub, [args] { return run_export(*args); }};
}

}  // namespace raintrace::cli
