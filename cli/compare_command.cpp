// Placeholder: `raintrace compare` until its owner lands it.
#include <CLI/CLI.hpp>
#include <stdexcept>

#include "cli/command.h"

namespace raintrace::cli {

Command register_compare_command(CLI::App& app) {
  auto* sub = app.add_subcommand("compare", "(not available yet)");
  return {sub, [] () -> int { throw std::runtime_error("'compare' is not available yet"); }};
}

}  // namespace raintrace::cli
