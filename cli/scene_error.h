// How a scene-file problem is worded: one line, "SOURCE:LINE:COL: KEY: what is wrong".
// Whatever the user wrote (keys, strings, file names) is escaped so that a hostile scene file
// can neither break the message over several lines nor send terminal control sequences.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "cli/scene_document.h"

namespace raintrace::cli {

/// `text` with every byte outside printable ASCII written as \n, \t, \\ or \xNN.
std::string escaped(std::string_view text);

/// `text` escaped, in double quotes, cut to max_chars characters of input with "…" after.
std::string in_quotes(std::string_view text, std::size_t max_chars = 60);

/// "SOURCE:LINE:COL: KEY: message" (the location part shrinks to "SOURCE:" when unknown and
/// the key part disappears when `key` is empty). SOURCE and KEY are escaped; message is taken
/// as is but any line break in it becomes a space.
std::string scene_error_text(std::string_view source, SourceLocation where, std::string_view key,
                             std::string_view message);

}  // namespace raintrace::cli
