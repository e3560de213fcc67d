// The `raintrace` program: parses the command line, runs one subcommand, and is the only place
// that turns an exception into one line for the user and an exit code.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <fmt/core.h>
#include <vector>

#include "cli/command.h"
#include "cli/exit_codes.h"

int main(int argc, char** argv) {
  namespace cli = raintrace::cli;
  CLI::App app{
      "raintrace: physically based rain, simulated and ray-traced with POV-Ray.\n"
      "Example: raintrace render examples/default.toml -o out/default"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string{"raintrace " RAINTRACE_VERSION});
  const std::vector<cli::Command> commands{
      cli::register_simulate_command(app), cli::register_export_command(app),
      cli::register_render_command(app), cli::register_compare_command(app)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    for (const auto& command : commands) {
      if (command.subcommand->parsed()) return command.run();
    }
  } catch (const std::exception& e) {
    std::fflush(stdout);
    fmt::print(stderr, "raintrace: error: {}\n", e.what());
    return cli::exit_code::error;
  }
  return cli::exit_code::error;
}
