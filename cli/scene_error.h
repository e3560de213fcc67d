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

/// `text` escaped, cut to max_chars bytes of input with "…" after: how anything a user wrote is
/// quoted in a message (a 15 MB key must not be echoed whole).
std::string shortened(std::string_view text, std::size_t max_chars = 60);

/// shortened(text, max_chars) in double quotes (a quote inside is escaped).
std::string in_quotes(std::string_view text, std::size_t max_chars = 60);

/// "SOURCE:LINE:COL: KEY: message" (the location part shrinks to "SOURCE:" when unknown and
/// the key part disappears when `key` is empty). SOURCE and KEY are escaped and shortened (to 200
/// and 80 bytes); message is taken as is but any line break in it becomes a space.
std::string scene_error_text(std::string_view source, SourceLocation where, std::string_view key,
                             std::string_view message);

}  // namespace raintrace::cli
