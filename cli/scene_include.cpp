// Validation of [environment] include; see scene_include.h for the rules and why.
#include "cli/scene_include.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <system_error>

#include "cli/scene_error.h"

namespace raintrace::cli {
namespace {

bool allowed_character(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '.' || c == '/' || c == '-';
}

/// True when `inner` (both canonical) is `outer` or lies below it.
bool lies_inside(const std::filesystem::path& inner, const std::filesystem::path& outer) {
  auto o = outer.begin();
  auto i = inner.begin();
  for (; o != outer.end(); ++o, ++i) {
    if (i == inner.end() || *i != *o) return false;
  }
  return true;
}

}  // namespace

std::filesystem::path validate_include_path(std::string_view text,
                                            const std::filesystem::path& base_dir) {
  namespace fs = std::filesystem;
  if (text.empty()) {
    throw std::invalid_argument("must not be empty (leave the key out to use the built-in)");
  }
  if (text.size() > 255) throw std::invalid_argument("must be at most 255 characters long");
  const auto bad = std::find_if_not(text.begin(), text.end(), allowed_character);
  if (bad != text.end()) {
    throw std::invalid_argument("must use only the characters A-Z a-z 0-9 _ . / - (got " +
                                in_quotes(std::string_view(&*bad, 1)) + " in " + in_quotes(text) +
                                ")");
  }
  if (text.front() == '/') {
    throw std::invalid_argument("must be relative to the scene file's folder, got absolute path " +
                                in_quotes(text));
  }
  if (text.size() < 5 || text.substr(text.size() - 4) != ".inc") {
    throw std::invalid_argument("must name a POV-Ray include ending in \".inc\", got " +
                                in_quotes(text));
  }
  const fs::path relative = fs::path(std::string{text}).lexically_normal();
  if (relative.empty() || *relative.begin() == "..") {
    throw std::invalid_argument("must stay inside the scene file's folder, got " + in_quotes(text));
  }
  const fs::path full = base_dir / relative;
  std::error_code error;
  if (!fs::is_regular_file(full, error)) {
    throw std::invalid_argument("no such file: " + in_quotes(full.string(), 200));
  }
  const fs::path real_file = fs::canonical(full, error);
  const fs::path real_base = error ? fs::path{} : fs::canonical(base_dir, error);
  if (error || !lies_inside(real_file, real_base)) {
    throw std::invalid_argument("must stay inside the scene file's folder (" + in_quotes(text) +
                                " leads outside it through a symbolic link)");
  }
  return relative;
}

}  // namespace raintrace::cli
