// docs/scene-format.md's generated columns (see scene_format_doc.h).
#include "cli/scene_format_doc.h"

#include <fmt/core.h>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "cli/scene_tables.h"

namespace raintrace::cli {
namespace {

/// Numbers as the docs print them: a typographic minus, and powers of ten from 1e5 on as
/// "1e5" ("[−1e5, 1e5]" reads better than "[-100000, 100000]").
std::string doc_number(double value) {
  std::string text;
  const double magnitude = std::fabs(value);
  const double exponent = std::log10(magnitude);
  if (magnitude >= 1e5 && exponent == std::floor(exponent)) {
    text = fmt::format("1e{}", static_cast<int>(exponent));
  } else {
    text = fmt::format("{}", magnitude);
  }
  return value < 0 ? "\u2212" + text : text;
}

std::string doc_integer(int value) {
  return value < 0 ? "\u2212" + std::to_string(-static_cast<long long>(value))
                   : std::to_string(value);
}

std::string doc_vector(const glm::dvec3& v) {
  return "[" + doc_number(v.x) + ", " + doc_number(v.y) + ", " + doc_number(v.z) + "]";
}

std::string doc_range(const sim::Range& range) {
  const bool has_min = std::isfinite(range.min);
  const bool has_max = std::isfinite(range.max);
  if (has_min && has_max) {
    return std::string{range.min_open ? "(" : "["} + doc_number(range.min) + ", " +
           doc_number(range.max) + (range.max_open ? ")" : "]");
  }
  if (has_min) return (range.min_open ? "> " : "\u2265 ") + doc_number(range.min);
  if (has_max) return (range.max_open ? "< " : "\u2264 ") + doc_number(range.max);
  return "";
}

std::string quoted_names(std::span<const std::string_view> names) {
  std::string text;
  for (const std::string_view name : names) {
    text += (text.empty() ? "`\"" : ", `\"") + std::string{name} + "\"`";
  }
  return text;
}

const char* type_name(sim::ParamType type) {
  switch (type) {
    case sim::ParamType::number:
      return "number";
    case sim::ParamType::integer:
    case sim::ParamType::seed:
      return "integer";
    case sim::ParamType::boolean:
      return "boolean";
    case sim::ParamType::vector:
      return "vector";
    case sim::ParamType::colour:
      return "colour";
    case sim::ParamType::choice:
    case sim::ParamType::text:
      break;
  }
  return "string";
}

template <class P>
SceneFormatRow doc_row(const sim::Param<P>& row, const P& defaults) {
  SceneFormatRow out;
  out.section = row.section;
  out.key = row.key;
  out.type = type_name(row.type);
  out.unit = row.unit.empty() ? "\u2014" : std::string{row.unit};
  std::visit(
      [&](const auto& field) {
        using Field = std::decay_t<decltype(field)>;
        if constexpr (std::is_same_v<Field, double P::*>) {
          out.default_text = doc_number(defaults.*field);
          out.range = doc_range(row.range);
        } else if constexpr (std::is_same_v<Field, int P::*>) {
          out.default_text = doc_integer(defaults.*field);
          out.range = "[" + doc_integer(static_cast<int>(row.range.min)) + ", " +
                      doc_integer(static_cast<int>(row.range.max)) + "]";
        } else if constexpr (std::is_same_v<Field, std::uint64_t P::*>) {
          out.default_text = std::to_string(defaults.*field);
          out.range = "[0, 2\u2076\u00b3\u22121]";  // what a TOML integer can hold
        } else if constexpr (std::is_same_v<Field, bool P::*>) {
          out.default_text = defaults.*field ? "true" : "false";
        } else if constexpr (std::is_same_v<Field, glm::dvec3 P::*>) {
          out.default_text = doc_vector(defaults.*field);
          out.range = "each in " + doc_range(row.range);
        } else if constexpr (std::is_same_v<Field, std::string P::*>) {
          out.default_text = "`\"" + defaults.*field + "\"`";
        } else {
          const std::size_t index = field.get(defaults, field.names);
          out.default_text = "`\"" + std::string{field.names[index]} + "\"`";
          out.range = quoted_names(field.names);
        }
      },
      row.field);
  if (!row.unset_name.empty()) out.default_text = row.unset_name;
  auto add = [&](const std::string& words) {
    out.range += (out.range.empty() ? "" : "; ") + words;
  };
  if (row.order == sim::Order::at_most) add("\u2264 `" + std::string{row.other} + "`");
  if (row.order == sim::Order::greater_than) add("> `" + std::string{row.other} + "`");
  if (!row.note.empty()) add(std::string{row.note});
  return out;
}

std::string table_line(const SceneFormatRow& row, std::string_view meaning) {
  return "| `" + row.key + "` | " + row.type + " | " + row.unit + " | " + row.default_text + " | " +
         (row.range.empty() ? "" : row.range + " ") + "| " + std::string{meaning} + " |";
}

/// The section a "## …" heading documents: "" for "## Top level", "rain" for "## `[rain]`";
/// false for other headings.
bool heading_section(std::string_view line, std::string& section) {
  if (line == "## Top level") {
    section.clear();
    return true;
  }
  if (line.rfind("## `[", 0) == 0 && line.size() > 8 && line.substr(line.size() - 2) == "]`") {
    section = std::string{line.substr(5, line.size() - 7)};
    return true;
  }
  return false;
}

}  // namespace

std::vector<SceneFormatRow> scene_format_rows() {
  const Scene defaults;
  std::vector<SceneFormatRow> rows;
  for (const std::string_view section : kSections) {
    for_each_table(defaults, [&](auto table, const auto& object) {
      for (const auto& row : table) {
        if (row.section == section) rows.push_back(doc_row(row, object));
      }
    });
  }
  return rows;
}

std::string update_scene_format_doc(std::string_view markdown) {
  std::map<std::pair<std::string, std::string>, SceneFormatRow> by_key;
  std::map<std::string, std::vector<SceneFormatRow>> by_section;
  for (const SceneFormatRow& row : scene_format_rows()) {
    by_key[{row.section, row.key}] = row;
    by_section[row.section].push_back(row);
  }
  std::map<std::pair<std::string, std::string>, bool> documented;

  std::istringstream in{std::string{markdown}};
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);

  std::string out;
  bool in_section = false;
  std::string section;
  bool seen_table = false;
  // Adds the rows of the section's keys the doc lacks, once its table ends.
  auto close_table = [&] {
    if (!in_section || !seen_table) return;
    for (const SceneFormatRow& row : by_section[section]) {
      bool& done = documented[{row.section, row.key}];
      if (!done) out += table_line(row, "TODO") + "\n";
      done = true;
    }
    seen_table = false;
  };
  for (const std::string& line : lines) {
    const bool is_row = line.rfind("| `", 0) == 0;
    if (!is_row && seen_table) close_table();
    if (line.rfind("## ", 0) == 0) in_section = heading_section(line, section);
    if (in_section && is_row) {
      seen_table = true;
      // | `key` | type | unit | default | range | meaning |
      std::vector<std::size_t> bars;
      for (std::size_t i = 0; i < line.size() && bars.size() < 6; ++i) {
        if (line[i] == '|') bars.push_back(i);
      }
      const std::size_t end = line.rfind('|');
      if (bars.size() < 6 || end <= bars[5]) {
        throw std::runtime_error("docs/scene-format.md: a key row without six cells: " + line);
      }
      const std::string key = line.substr(bars[0] + 3, line.find('`', bars[0] + 3) - bars[0] - 3);
      const auto found = by_key.find({section, key});
      if (found == by_key.end()) {
        throw std::runtime_error(fmt::format(
            "docs/scene-format.md documents {} but no parameter table has it (sim/params.h, "
            "sim/camera.h, povgen/export_params.h, cli/scene.h)",
            sim::full_key(section, key)));
      }
      documented[{section, key}] = true;
      std::string meaning = line.substr(bars[5] + 1, end - bars[5] - 1);
      const std::size_t first = meaning.find_first_not_of(' ');
      const std::size_t last = meaning.find_last_not_of(' ');
      meaning = first == std::string::npos ? "" : meaning.substr(first, last - first + 1);
      out += table_line(found->second, meaning) + "\n";
      continue;
    }
    out += line + "\n";
  }
  close_table();
  for (const auto& [where, row] : by_key) {
    if (!documented[where]) {
      throw std::runtime_error(fmt::format(
          "docs/scene-format.md has no table for the section of {} (add a \"## `[{}]`\" "
          "heading with a key table)",
          sim::full_key(where.first, where.second), where.first));
    }
  }
  if (!markdown.empty() && markdown.back() != '\n') out.pop_back();
  return out;
}

}  // namespace raintrace::cli
