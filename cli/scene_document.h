// The scene file as a plain tree of values that remember where they were written. The TOML
// parser (toml++) is confined to scene_toml.cpp, which builds this tree; everything that
// validates values works on the tree, so toml++ never reaches a header and the reader can be
// tested on hand-built trees.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace raintrace::cli {

/// 1-based line and column in the scene file; 0 when unknown.
struct SourceLocation {
  int line = 0;
  int column = 0;
};

struct SceneEntry;

/// One value of the document: a scalar, an array or a table.
struct SceneNode {
  enum class Kind { integer, floating, boolean, string, array, table, other };

  Kind kind = Kind::table;
  SourceLocation where;             ///< where the value starts
  std::int64_t integer = 0;         ///< Kind::integer
  double floating = 0.0;            ///< Kind::floating (may be inf or nan: TOML allows them)
  bool boolean = false;             ///< Kind::boolean
  std::string string;               ///< Kind::string; for Kind::other the TOML type's name
  std::vector<SceneNode> items;     ///< Kind::array
  std::vector<SceneEntry> entries;  ///< Kind::table, in the order toml++ keeps them
};

struct SceneEntry {
  std::string key;
  SourceLocation where;  ///< where the key is written
  SceneNode value;
};

/// Parses TOML text into the tree. Throws SceneError "SOURCE:LINE:COL: syntax error: …" when
/// the text is not valid TOML.
SceneNode parse_scene_document(std::string_view text, const std::string& source_name);

/// "integer", "float", "boolean", "string", "array", "table" or the TOML type's own name.
std::string kind_name(const SceneNode& node);

}  // namespace raintrace::cli
