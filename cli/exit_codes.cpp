// Mapping errors to exit codes and message lines.
#include "cli/exit_codes.h"

#include <fmt/core.h>
#include <algorithm>
#include <string_view>
#include <system_error>

#include "output/folder_lock.h"

namespace raintrace::cli {
namespace {
constexpr std::size_t kMaxErrorLine = 1000;
}  // namespace

int exit_code_for(const std::exception& e) {
  if (dynamic_cast<const output::FolderBusy*>(&e) != nullptr) return exit_code::busy;
  if (dynamic_cast<const std::system_error*>(&e) != nullptr) return exit_code::system_error;
  return exit_code::error;
}

std::string error_line(const std::exception& e) {
  std::string_view text = e.what();
  std::string line;
  std::size_t shown = std::min(text.size(), kMaxErrorLine);
  // Never cut a UTF-8 character in two: back up to the start of the one at the cut.
  while (shown > 0 && shown < text.size() &&
         (static_cast<unsigned char>(text[shown]) & 0xC0) == 0x80) {
    --shown;
  }
  for (const char c : text.substr(0, shown)) line += (c == '\n' || c == '\r') ? ' ' : c;
  if (shown < text.size()) {
    line += fmt::format("… ({} more characters not shown)", text.size() - shown);
  }
  return line;
}

}  // namespace raintrace::cli
