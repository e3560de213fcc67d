// The built-in POV-Ray includes from templates/, compiled into the program (so an installed
// raintrace needs no data folder), and the checks that keep user-chosen names and paths from
// turning into POV-Ray text.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "povgen/export_params.h"

namespace raintrace::povgen {

/// Names of the built-in environments: "night_street", "field", "closeup".
const std::vector<std::string>& builtin_environments();

/// Text of a built-in environment. Throws std::invalid_argument for any other name (the name
/// is quoted in the message with non-printable characters replaced, never in POV-Ray text).
const std::string& environment_template(std::string_view name);

/// Text of templates/raintrace_materials.inc (drop, streak, splash and bolt materials).
const std::string& materials_template();

/// Text of templates/raintrace_ground.inc (puddles and ripples: the RT_WetGround macro).
const std::string& ground_template();

/// The environment.inc to write for these params: the built-in template, or the bytes of the
/// user's include ([environment] include_path, relative to scene_dir). The user's path is
/// re-checked here: relative, no "..", inside scene_dir after resolving links, a regular file.
/// Throws std::invalid_argument naming the problem.
std::string environment_text(const EnvironmentParams& environment,
                             const std::filesystem::path& scene_dir);

/// `text` made safe to quote in a message: printable ASCII kept, the rest as '?', cut at 80.
std::string printable(std::string_view text);

}  // namespace raintrace::povgen
