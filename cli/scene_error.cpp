// Wording of scene-file errors; see scene_error.h.
#include "cli/scene_error.h"

#include <fmt/core.h>

namespace raintrace::cli {

std::string escaped(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\\') {
      out += "\\\\";
    } else if (byte < 0x20 || byte >= 0x7f) {
      // Non-ASCII too: a UTF-8 C1 control (U+0080–U+009F) is a terminal escape on some terminals.
      out += fmt::format("\\x{:02x}", byte);
    } else {
      out += c;
    }
  }
  return out;
}

std::string shortened(std::string_view text, std::size_t max_chars) {
  return text.size() > max_chars ? escaped(text.substr(0, max_chars)) + "…" : escaped(text);
}

std::string in_quotes(std::string_view text, std::size_t max_chars) {
  const bool cut = text.size() > max_chars;
  std::string out = "\"";
  for (const char c : escaped(cut ? text.substr(0, max_chars) : text)) {
    if (c == '"') out += '\\';  // a quote inside the value would make the message ambiguous
    out += c;
  }
  out += cut ? "\"…" : "\"";
  return out;
}

std::string scene_error_text(std::string_view source, SourceLocation where, std::string_view key,
                             std::string_view message) {
  std::string out = shortened(source, 200);
  if (where.line > 0) out += fmt::format(":{}:{}", where.line, where.column);
  out += ": ";
  if (!key.empty()) {
    out += shortened(key, 80);
    out += ": ";
  }
  for (const char c : message) out += (c == '\n' || c == '\r') ? ' ' : c;
  return out;
}

}  // namespace raintrace::cli
