// A guard in front of the TOML parser. Debian 12 ships toml++ 3.3.0, whose Unicode whitespace
// test reaches __builtin_unreachable (undefined behaviour) for many non-ASCII code points
// (marzer/tomlplusplus#190 and #295, fixed upstream by #305); fuzz/fuzz_scene found it within
// seconds. No key or value of the scene format needs non-ASCII text, so the loader refuses
// non-ASCII bytes everywhere except in comments before toml++ sees the text.
#pragma once

#include <optional>
#include <string_view>

#include "cli/scene_document.h"

namespace raintrace::cli {

/// Where the first byte >= 0x80 outside a comment is, if any. Follows TOML's four string forms
/// (basic, literal and their multi-line variants, with escapes) closely enough to know whether
/// a '#' starts a comment.
std::optional<SourceLocation> first_non_ascii_outside_comments(std::string_view text);

}  // namespace raintrace::cli
