// The non-ASCII guard in front of toml++; see scene_ascii.h for why.
#include "cli/scene_ascii.h"

#include <cstddef>

namespace raintrace::cli {

std::optional<SourceLocation> first_non_ascii_outside_comments(std::string_view text) {
  enum class State { normal, comment, basic, literal, multi_basic, multi_literal };
  constexpr std::string_view kTripleQuote = R"(""")";
  constexpr std::string_view kTripleApostrophe = R"(''')";
  State state = State::normal;
  int line = 1;
  std::size_t line_start = 0;
  const auto starts = [&](std::size_t i, std::string_view token) {
    return text.substr(i, token.size()) == token;
  };
  // Closing a multi-line string: up to two more quote characters still belong to it
  // ("""a""""" is the string a"").
  const auto close_multi = [&](std::size_t& i, char quote) {
    i += 2;
    for (int extra = 0; extra < 2 && i + 1 < text.size() && text[i + 1] == quote; ++extra) ++i;
    state = State::normal;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      line_start = i + 1;
      // A newline ends a comment, and a single-line string (toml++ then reports that).
      if (state != State::multi_basic && state != State::multi_literal) state = State::normal;
      continue;
    }
    if (static_cast<unsigned char>(c) >= 0x80 && state != State::comment) {
      // Everything before it on this line is ASCII, so bytes count columns like toml++ does.
      return SourceLocation{line, static_cast<int>(i - line_start) + 1};
    }
    switch (state) {
      case State::normal:
        if (c == '#') {
          state = State::comment;
        } else if (starts(i, kTripleQuote)) {
          state = State::multi_basic;
          i += 2;
        } else if (starts(i, kTripleApostrophe)) {
          state = State::multi_literal;
          i += 2;
        } else if (c == '"') {
          state = State::basic;
        } else if (c == '\'') {
          state = State::literal;
        }
        break;
      case State::comment:
        break;
      case State::basic:
        if (c == '\\' && i + 1 < text.size() && text[i + 1] != '\n') {
          ++i;  // the escaped character cannot end the string
        } else if (c == '"') {
          state = State::normal;
        }
        break;
      case State::literal:
        if (c == '\'') state = State::normal;
        break;
      case State::multi_basic:
        if (c == '\\' && i + 1 < text.size() && text[i + 1] != '\n') {
          ++i;
        } else if (starts(i, kTripleQuote)) {
          close_multi(i, '"');
        }
        break;
      case State::multi_literal:
        if (starts(i, kTripleApostrophe)) close_multi(i, '\'');
        break;
    }
  }
  return std::nullopt;
}

}  // namespace raintrace::cli
