// Typed, located reads of one scene-file table; see scene_reader.h.
#include "cli/scene_reader.h"

#include <fmt/core.h>
#include <algorithm>
#include <cctype>
#include <cmath>

#include "cli/scene.h"
#include "cli/scene_error.h"

namespace raintrace::cli {
namespace {

/// How a value is quoted after "got": the value itself for scalars, its kind otherwise.
std::string describe_value(const SceneNode& node) {
  switch (node.kind) {
    case SceneNode::Kind::integer:
      return fmt::format("{}", node.integer);
    case SceneNode::Kind::floating:
      return fmt::format("{}", node.floating);
    case SceneNode::Kind::boolean:
      return node.boolean ? "true" : "false";
    case SceneNode::Kind::string:
      return "string " + in_quotes(node.string);
    case SceneNode::Kind::array:
      return fmt::format("an array of {} element{}", node.items.size(),
                         node.items.size() == 1 ? "" : "s");
    case SceneNode::Kind::table:
      return "a table";
    case SceneNode::Kind::other:
      break;
  }
  return "a " + node.string;
}

std::string join_quoted(std::span<const std::string_view> names) {
  std::string out;
  for (const auto& name : names) {
    if (!out.empty()) out += ", ";
    out += in_quotes(name);
  }
  return out;
}

const SceneNode& empty_table() {
  static const SceneNode table;  // Kind::table, no entries, unknown location
  return table;
}

}  // namespace

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Optimal string alignment distance: Levenshtein plus adjacent transpositions, so that
  // "rian" is one edit from "rain", as a typist would count it.
  const auto fold = [](char c) {
    return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  };
  const std::size_t n = a.size();
  const std::size_t m = b.size();
  std::vector<std::size_t> d((n + 1) * (m + 1));
  const auto at = [&](std::size_t i, std::size_t j) -> std::size_t& { return d[i * (m + 1) + j]; };
  for (std::size_t i = 0; i <= n; ++i) at(i, 0) = i;
  for (std::size_t j = 0; j <= m; ++j) at(0, j) = j;
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = fold(a[i - 1]) == fold(b[j - 1]) ? 0 : 1;
      at(i, j) = std::min({at(i - 1, j) + 1, at(i, j - 1) + 1, at(i - 1, j - 1) + cost});
      if (i > 1 && j > 1 && fold(a[i - 1]) == fold(b[j - 2]) && fold(a[i - 2]) == fold(b[j - 1])) {
        at(i, j) = std::min(at(i, j), at(i - 2, j - 2) + 1);
      }
    }
  }
  return at(n, m);
}

std::optional<std::string> closest_name(std::string_view name,
                                        const std::vector<std::string>& candidates) {
  // Allow about one typo per three characters, at least one and at most three; a name that
  // long user input needs (a pasted path, say) never gets a suggestion.
  if (name.size() > 200) return std::nullopt;
  const std::size_t allowed = std::clamp<std::size_t>(name.size() / 3, 1, 3);
  std::optional<std::string> best;
  std::size_t best_distance = allowed + 1;
  for (const auto& candidate : candidates) {
    const std::size_t distance = edit_distance(name, candidate);
    if (distance < best_distance) {
      best_distance = distance;
      best = candidate;
    }
  }
  return best;
}

TableReader::TableReader(const SceneNode& table, std::string section, std::string source)
    : m_table(table), m_section(std::move(section)), m_source(std::move(source)) {}

std::string TableReader::full_key(std::string_view key) const {
  return m_section.empty() ? std::string{key} : m_section + "." + std::string{key};
}

const SceneNode* TableReader::find(std::string_view key) {
  if (std::find(m_known.begin(), m_known.end(), key) == m_known.end()) {
    m_known.emplace_back(key);
  }
  for (const auto& entry : m_table.entries) {
    if (entry.key == key) return &entry.value;
  }
  return nullptr;
}

std::optional<SourceLocation> TableReader::where(std::string_view key) const {
  for (const auto& entry : m_table.entries) {
    if (entry.key == key) return entry.value.where;
  }
  return std::nullopt;
}

void TableReader::fail_at(SourceLocation where, const std::string& key,
                          std::string_view message) const {
  throw SceneError(scene_error_text(m_source, where, key, message));
}

void TableReader::fail(std::string_view key, std::string_view message) const {
  fail_at(where(key).value_or(m_table.where), full_key(key), message);
}

double TableReader::number_of(const SceneNode& node, const std::string& key) const {
  if (node.kind == SceneNode::Kind::integer) return static_cast<double>(node.integer);
  if (node.kind != SceneNode::Kind::floating) {
    fail_at(node.where, key, "expected a number, got " + describe_value(node));
  }
  if (!std::isfinite(node.floating)) {
    fail_at(node.where, key, "must be a finite number, got " + describe_value(node));
  }
  return node.floating;
}

bool TableReader::read_number(std::string_view key, double& out, const Range& range) {
  const SceneNode* node = find(key);
  if (node == nullptr) return false;
  const double value = number_of(*node, full_key(key));
  if (!range.contains(value)) {
    fail_at(node->where, full_key(key),
            fmt::format("must be {}, got {}", range.describe(), describe_value(*node)));
  }
  out = value;
  return true;
}

bool TableReader::read_integer(std::string_view key, int& out, int min, int max) {
  const SceneNode* node = find(key);
  if (node == nullptr) return false;
  if (node->kind != SceneNode::Kind::integer) {
    const std::string got = node->kind == SceneNode::Kind::floating
                                ? "float " + describe_value(*node)
                                : describe_value(*node);
    fail_at(node->where, full_key(key), "expected an integer, got " + got);
  }
  if (node->integer < min || node->integer > max) {
    fail_at(node->where, full_key(key),
            fmt::format("must be in [{}, {}], got {}", min, max, node->integer));
  }
  out = static_cast<int>(node->integer);
  return true;
}

bool TableReader::read_unsigned(std::string_view key, std::uint64_t& out) {
  const SceneNode* node = find(key);
  if (node == nullptr) return false;
  if (node->kind != SceneNode::Kind::integer) {
    const std::string got = node->kind == SceneNode::Kind::floating
                                ? "float " + describe_value(*node)
                                : describe_value(*node);
    fail_at(node->where, full_key(key), "expected an integer, got " + got);
  }
  if (node->integer < 0) {
    fail_at(node->where, full_key(key), fmt::format("must be >= 0, got {}", node->integer));
  }
  out = static_cast<std::uint64_t>(node->integer);
  return true;
}

bool TableReader::read_bool(std::string_view key, bool& out) {
  const SceneNode* node = find(key);
  if (node == nullptr) return false;
  if (node->kind != SceneNode::Kind::boolean) {
    fail_at(node->where, full_key(key), "expected true or false, got " + describe_value(*node));
  }
  out = node->boolean;
  return true;
}

bool TableReader::read_string(std::string_view key, std::string& out) {
  const SceneNode* node = find(key);
  if (node == nullptr) return false;
  if (node->kind != SceneNode::Kind::string) {
    fail_at(node->where, full_key(key), "expected a string, got " + describe_value(*node));
  }
  out = node->string;
  return true;
}

bool TableReader::read_vec3(std::string_view key, glm::dvec3& out, const Range& each) {
  const SceneNode* node = find(key);
  if (node == nullptr) return false;
  if (node->kind != SceneNode::Kind::array || node->items.size() != 3) {
    fail_at(node->where, full_key(key),
            "expected an array of 3 numbers [x, y, z], got " + describe_value(*node));
  }
  glm::dvec3 value{0.0};
  for (int i = 0; i < 3; ++i) {
    const SceneNode& item = node->items[static_cast<std::size_t>(i)];
    const std::string item_key = fmt::format("{}[{}]", full_key(key), i);
    value[i] = number_of(item, item_key);
    if (!each.contains(value[i])) {
      fail_at(item.where, item_key,
              fmt::format("must be {}, got {}", each.describe(), describe_value(item)));
    }
  }
  out = value;
  return true;
}

std::optional<std::size_t> TableReader::read_choice(std::string_view key,
                                                    std::span<const std::string_view> names) {
  const SceneNode* node = find(key);
  if (node == nullptr) return std::nullopt;
  if (node->kind == SceneNode::Kind::string) {
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (node->string == names[i]) return i;
    }
  }
  std::string message =
      fmt::format("expected one of {}, got {}", join_quoted(names), describe_value(*node));
  if (node->kind == SceneNode::Kind::string) {
    const std::vector<std::string> candidates(names.begin(), names.end());
    if (const auto guess = closest_name(node->string, candidates)) {
      message += fmt::format(" (did you mean {}?)", in_quotes(*guess));
    }
  }
  fail_at(node->where, full_key(key), message);
}

TableReader TableReader::section(std::string_view key) {
  const SceneNode* node = find(key);
  const std::string name = full_key(key);
  if (node == nullptr) return TableReader(empty_table(), name, m_source);
  if (node->kind != SceneNode::Kind::table) {
    fail_at(node->where, name,
            fmt::format("expected a table (a [{}] section), got {}", name, describe_value(*node)));
  }
  return TableReader(*node, name, m_source);
}

void TableReader::finish() const {
  for (const auto& entry : m_table.entries) {
    if (std::find(m_known.begin(), m_known.end(), entry.key) != m_known.end()) continue;
    const bool is_section = m_section.empty() && entry.value.kind == SceneNode::Kind::table;
    std::string message = is_section ? "unknown section" : "unknown key";
    if (const auto guess = closest_name(entry.key, m_known)) {
      message += fmt::format(" (did you mean '{}'?)", escaped(*guess));
    } else {
      std::string known;
      for (const auto& name : m_known) known += (known.empty() ? "" : ", ") + name;
      message += m_section.empty() ? fmt::format(" (known: {})", known)
                                   : fmt::format(" (known keys of [{}]: {})", m_section, known);
    }
    fail_at(entry.where, full_key(entry.key), message);
  }
}

}  // namespace raintrace::cli
