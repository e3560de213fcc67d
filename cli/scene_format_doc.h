// The generated columns of docs/scene-format.md. For every key of the parameter tables
// (scene_tables.h) it makes the type, unit, default and range cells the docs' tables show, so
// the docs cannot drift from the code: a test checks them, and
// `cmake --build build --target update-scene-format` rewrites them in place. The last column
// (what the key means) is written by hand and left alone.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace raintrace::cli {

struct SceneFormatRow {
  std::string section;  ///< "rain"; "" for the top level
  std::string key;
  std::string type;          ///< "number", "integer", "boolean", "vector", "colour", "string"
  std::string unit;          ///< "mm/h", or "—"
  std::string default_text;  ///< "5", "[0, 1.6, −5]", "`\"preview\"`", "automatic"
  std::string range;         ///< "[0, 500]", "(0, 1000]; > `near_m`", "" for booleans
};

/// Every key of a scene file, section by section in file order.
std::vector<SceneFormatRow> scene_format_rows();

/// `markdown` (docs/scene-format.md) with the key, type, unit, default and range cells of every
/// key row regenerated. A key the doc lacks gets a row at the end of its section's table, its
/// meaning "TODO". Throws std::runtime_error naming a documented key that no table has, or a
/// section whose table is missing.
std::string update_scene_format_doc(std::string_view markdown);

}  // namespace raintrace::cli
