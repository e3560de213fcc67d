// The `raintrace` program: parses the command line, runs one subcommand, and is the only place
// that turns an exception into one line for the user and an exit code.
#include <fmt/core.h>
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <vector>

#include "cli/command.h"
#include "cli/exit_codes.h"

namespace {

constexpr const char* kFooter = R"(
Commands, each with an example (`raintrace COMMAND --help` shows all options and more):
  simulate  rain statistics without rendering
            raintrace simulate examples/default.toml --stats stats.json
  export    POV-Ray files only (plain `povray scene.ini` renders them)
            raintrace export examples/default.toml -o out/default
  render    simulate, export and ray-trace with POV-Ray, then movie and contact sheet
            raintrace render examples/default.toml -o out/default
  compare   image metrics and a difference report between two images or folders
            raintrace compare tests/reference/default out/default/images

Scene files: docs/scene-format.md; examples: examples/*.toml.
Exit codes: 0 success, 1 partly failed (frames, image differences), 2 unusable input,
3 system error (disk full, permission denied), 4 output folder in use by another run.)";

}  // namespace

int main(int argc, char** argv) {
  namespace cli = raintrace::cli;
  CLI::App app{
      "raintrace: physically based rain, simulated and ray-traced with POV-Ray.\n"
      "Example: raintrace render examples/default.toml -o out/default"};
  app.footer(kFooter);
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string{"raintrace " RAINTRACE_VERSION});
  const std::vector<cli::Command> commands{
      cli::register_simulate_command(app), cli::register_export_command(app),
      cli::register_render_command(app), cli::register_compare_command(app)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; every real parse error is "bad option", exit code 2.
    const int code = app.exit(e);
    return code == 0 ? cli::exit_code::ok : cli::exit_code::error;
  }
  try {
    for (const auto& command : commands) {
      if (command.subcommand->parsed()) return command.run();
    }
  } catch (const std::exception& e) {
    std::fflush(stdout);
    fmt::print(stderr, "raintrace: error: {}\n", cli::error_line(e));
    return cli::exit_code_for(e);
  }
  return cli::exit_code::error;
}
