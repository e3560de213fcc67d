// Placeholder: `raintrace simulate` until its owner lands it.
#include <CLI/CLI.hpp>
#include <stdexcept>

#include "cli/command.h"

namespace raintrace::cli {

Command register_simulate_command(CLI::App& app) {
  auto* sub = app.add_subcommand("simulate", "(not available yet)");
  return {sub, [] () -> int { throw std::runtime_error("'simulate' is not available yet"); }};
}

}  // namespace raintrace::cli
