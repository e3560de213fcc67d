// How a subcommand plugs into the `raintrace` program: each <name>_command.cpp registers its
// options on the CLI11 app and returns the function that runs it. Only main() prints errors and
// chooses exit codes; a command returns its exit code or throws.
#pragma once

#include <functional>

namespace CLI {
class App;
}

namespace raintrace::cli {

struct Command {
  CLI::App* subcommand = nullptr;  ///< the parsed subcommand, owned by the app
  std::function<int()> run;        ///< runs it once options are parsed; returns the exit code
};

Command register_simulate_command(CLI::App& app);
Command register_export_command(CLI::App& app);
Command register_render_command(CLI::App& app);
Command register_compare_command(CLI::App& app);

}  // namespace raintrace::cli
