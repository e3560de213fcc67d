// The one user-supplied path that reaches POV-Ray text: [environment] include. POV-Ray in
// Debian does not enforce its file-access restrictions (docs/povray-notes.md), so an include is a
// program with the user's rights: it must be a plain, relative .inc inside the scene's folder.
#pragma once

#include <filesystem>
#include <string_view>

namespace raintrace::cli {

/// Checks `text` and returns it in normal form, relative to base_dir. The rules, in the order
/// they are checked: not empty, at most 255 characters, only [A-Za-z0-9_./-] (so no quotes,
/// spaces, newlines, '#' or backslashes can reach POV-Ray text), not absolute, ends in ".inc",
/// does not leave base_dir through "..", names an existing regular file, and that file (symbolic
/// links resolved) lies inside base_dir. Throws std::invalid_argument naming the broken rule.
std::filesystem::path validate_include_path(std::string_view text,
                                            const std::filesystem::path& base_dir);

}  // namespace raintrace::cli
