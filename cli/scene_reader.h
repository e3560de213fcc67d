// Typed, located reads of one table of the scene file, in the manner of pbrt's parameter
// lists: each read leaves its target untouched when the key is absent (so defaults live only in
// the params structs), throws SceneError at the value when it is present but wrong, and
// finish() rejects every key nobody asked for, with a "did you mean" when one is close.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "cli/scene_document.h"
#include "sim/param_table.h"

namespace raintrace::cli {

/// The valid values of a number (the parameter tables' type).
using Range = sim::Range;

/// Edit distance (Levenshtein, ASCII case folded) between two names.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The candidate closest to `name`, if it is close enough to be a likely typo.
std::optional<std::string> closest_name(std::string_view name,
                                        const std::vector<std::string>& candidates);

class TableReader {
 public:
  /// `table` must outlive the reader. `section` prefixes keys in messages ("rain" gives
  /// "rain.rate_mm_per_h"); empty for the top level. `source` names the file in messages.
  TableReader(const SceneNode& table, std::string section, std::string source);

  bool read_number(std::string_view key, double& out, const Range& range);
  bool read_integer(std::string_view key, int& out, int min, int max);
  /// A non-negative integer of up to 63 bits (TOML integers are signed 64-bit).
  bool read_unsigned(std::string_view key, std::uint64_t& out);
  bool read_bool(std::string_view key, bool& out);
  bool read_string(std::string_view key, std::string& out);
  /// An array of exactly three numbers, each in `each`.
  bool read_vec3(std::string_view key, glm::dvec3& out, const Range& each);

  /// A string that must be one of `names`: its index in names.
  std::optional<std::size_t> read_choice(std::string_view key,
                                         std::span<const std::string_view> names);

  /// Reader over the sub-table `key` (a [section]); over an empty table when it is absent.
  TableReader section(std::string_view key);

  /// Where the value of `key` starts, when the key is present.
  [[nodiscard]] std::optional<SourceLocation> where(std::string_view key) const;

  /// Throws SceneError for `key` at its value (or at the table when absent).
  [[noreturn]] void fail(std::string_view key, std::string_view message) const;

  /// Throws SceneError at the first key in file order that no read_* or section() asked for.
  void finish() const;

  [[nodiscard]] const std::string& source() const { return m_source; }
  /// The section read ("rain"), empty at the top level.
  [[nodiscard]] const std::string& section_name() const { return m_section; }
  /// "rain.rate_mm_per_h" for key "rate_mm_per_h".
  [[nodiscard]] std::string full_key(std::string_view key) const;

 private:
  /// Marks `key` as known and returns its value, or nullptr when absent.
  const SceneNode* find(std::string_view key);
  /// A number from an integer or a float node; throws when it is neither, or not finite.
  double number_of(const SceneNode& node, const std::string& key) const;
  [[noreturn]] void fail_at(SourceLocation where, const std::string& key,
                            std::string_view message) const;

  const SceneNode& m_table;
  std::string m_section;
  std::string m_source;
  std::vector<std::string> m_known;
};

}  // namespace raintrace::cli
