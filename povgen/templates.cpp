// Built-in templates (embedded by CMake into templates_embedded.cpp) and include checks.
#include "povgen/templates.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace raintrace::povgen {

// Defined in the generated templates_embedded.cpp.
extern const char* const kNightStreetTemplate;
extern const char* const kFieldTemplate;
extern const char* const kCloseupTemplate;
extern const char* const kMaterialsTemplate;
extern const char* const kGroundTemplate;

const std::vector<std::string>& builtin_environments() {
  static const std::vector<std::string> names(std::begin(kEnvironmentNames),
                                              std::end(kEnvironmentNames));
  return names;
}

const std::string& environment_template(std::string_view name) {
  static const std::string night_street{kNightStreetTemplate};
  static const std::string field{kFieldTemplate};
  static const std::string closeup{kCloseupTemplate};
  if (name == "night_street") return night_street;
  if (name == "field") return field;
  if (name == "closeup") return closeup;
  throw std::invalid_argument("unknown environment '" + printable(name) +
                              "': use night_street, field or closeup");
}

const std::string& materials_template() {
  static const std::string text{kMaterialsTemplate};
  return text;
}

const std::string& ground_template() {
  static const std::string text{kGroundTemplate};
  return text;
}

std::string printable(std::string_view text) {
  std::string out;
  for (char c : text.substr(0, 80)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
  if (text.size() > 80) out += "...";
  return out;
}

std::string environment_text(const EnvironmentParams& environment,
                             const std::filesystem::path& scene_dir) {
  namespace fs = std::filesystem;
  if (environment.include_path.empty()) return environment_template(environment.name);

  const std::string& raw = environment.include_path;
  const fs::path relative{raw};
  const bool has_parent_step =
      std::any_of(relative.begin(), relative.end(), [](const fs::path& p) { return p == ".."; });
  if (raw.find('\0') != std::string::npos || relative.is_absolute() || relative.has_root_name() ||
      has_parent_step) {
    throw std::invalid_argument("environment include '" + printable(raw) +
                                "' must be a relative path inside the scene file's folder");
  }
  std::error_code error;
  const fs::path base = fs::canonical(scene_dir.empty() ? fs::path{"."} : scene_dir, error);
  if (error) {
    throw std::invalid_argument("environment include: cannot resolve the scene folder " +
                                printable(scene_dir.string()));
  }
  const fs::path resolved = fs::canonical(base / relative, error);
  if (error || !fs::is_regular_file(resolved)) {
    throw std::invalid_argument("environment include '" + printable(raw) +
                                "' is not a readable file in " + printable(base.string()));
  }
  // Symbolic links are resolved above: the real file must still lie inside the scene folder.
  const auto mismatch = std::mismatch(base.begin(), base.end(), resolved.begin(), resolved.end());
  if (mismatch.first != base.end()) {
    throw std::invalid_argument("environment include '" + printable(raw) +
                                "' leads outside the scene file's folder");
  }
  std::ifstream in(resolved, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (!in && !in.eof()) {
    throw std::invalid_argument("environment include '" + printable(raw) + "' cannot be read");
  }
  return bytes.str();
}

}  // namespace raintrace::povgen
