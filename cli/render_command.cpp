// Placeholder: `raintrace render` until its owner lands it.
#include <CLI/CLI.hpp>
#include <stdexcept>

#include "cli/command.h"

namespace raintrace::cli {

Command register_render_command(CLI::App& app) {
  auto* sub = app.add_subcommand("render", "(not available yet)");
  return {sub, [] () -> int { throw std::runtime_error("'render' is not available yet"); }};
}

}  // namespace raintrace::cli
