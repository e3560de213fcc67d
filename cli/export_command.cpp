// `raintrace export SCENE.toml -o OUT [--frames A-B] [--seed N]`: simulate a scene and write
// its POV-Ray output folder (scene.ini, scene.inc, frames/, textures/, manifest.json), which
// plain `povray scene.ini` renders from inside the folder.
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
#include "cli/export_pipeline.h"
#include "cli/options.h"
#include "cli/scene.h"

namespace raintrace::cli {
namespace {

struct ExportArgs {
  std::string scene;
  std::string out;
  std::string frames;
  std::optional<std::uint64_t> seed;
};

int run_export(const ExportArgs& args) {
  Scene scene = load_scene_file(args.scene);
  if (args.seed) scene.sim.seed = *args.seed;
  const FrameRange range = parse_frame_range(args.frames, scene.frames);
  const bool terminal = isatty(fileno(stderr)) != 0;
  fmt::print(stderr, "export: {} frames {}-{} of {} to {}\n", args.scene, range.first, range.last,
             scene.frames, args.out);
  int last_reported = 0;
  export_scene(scene, range, args.out, [&](const ExportProgress& p) {
    if (terminal) {
      fmt::print(stderr, "\rexport: frame {}/{}", p.frames_done, p.frames_total);
      if (p.frames_done == p.frames_total) fmt::print(stderr, "\n");
    } else if (p.frames_done == p.frames_total ||
               p.frames_done * 10 / p.frames_total > last_reported) {
      // Plain lines in logs: one per tenth of the work.
      last_reported = p.frames_done * 10 / p.frames_total;
      fmt::print(stderr, "export: frame {}/{}\n", p.frames_done, p.frames_total);
    }
  });
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
      "  cd out/night && povray scene.ini        # plain POV-Ray renders images/frame_NNNN.png");
  sub->add_option("scene", args->scene, "Scene file (.toml)")->required();
  sub->add_option("-o,--output", args->out, "Output folder (created if missing)")->required();
  sub->add_option("--frames", args->frames, "Frames to write: A-B or N (default: all)");
  add_seed_option(*sub, args->seed);
  return {sub, [args] { return run_export(*args); }};
}

}  // namespace raintrace::cli
