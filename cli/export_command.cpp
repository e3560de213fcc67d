// Placeholder: `raintrace export` until its owner lands it.
#include <CLI/CLI.hpp>
#include <stdexcept>

#include "cli/command.h"

namespace raintrace::cli {

Command register_export_command(CLI::App& app) {
  auto* sub = app.add_subcommand("export", "(not available yet)");
  return {sub, [] () -> int { throw std::runtime_error("'export' is not available yet"); }};
}

}  // namespace raintrace::cli
