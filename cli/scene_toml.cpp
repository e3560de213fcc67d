// The only place toml++ is used: TOML text → SceneNode tree (scene_document.h). Entries are
// put back into file order (toml++ keeps tables sorted by key) so that problems are reported
// in the order a reader meets them.
#include <toml++/toml.h>
#include <algorithm>

#include "cli/scene.h"
#include "cli/scene_ascii.h"
#include "cli/scene_document.h"
#include "cli/scene_error.h"

namespace raintrace::cli {
namespace {

SourceLocation location_of(const toml::source_region& region) {
  return {static_cast<int>(region.begin.line), static_cast<int>(region.begin.column)};
}

bool before(const SourceLocation& a, const SourceLocation& b) {
  return a.line != b.line ? a.line < b.line : a.column < b.column;
}

SceneNode convert(const toml::node& node) {
  SceneNode out;
  out.where = location_of(node.source());
  switch (node.type()) {
    case toml::node_type::integer:
      out.kind = SceneNode::Kind::integer;
      out.integer = node.as_integer()->get();
      break;
    case toml::node_type::floating_point:
      out.kind = SceneNode::Kind::floating;
      out.floating = node.as_floating_point()->get();
      break;
    case toml::node_type::boolean:
      out.kind = SceneNode::Kind::boolean;
      out.boolean = node.as_boolean()->get();
      break;
    case toml::node_type::string:
      out.kind = SceneNode::Kind::string;
      out.string = node.as_string()->get();
      break;
    case toml::node_type::array:
      out.kind = SceneNode::Kind::array;
      for (const toml::node& item : *node.as_array()) out.items.push_back(convert(item));
      break;
    case toml::node_type::table:
      out.kind = SceneNode::Kind::table;
      for (const auto& [key, value] : *node.as_table()) {
        SourceLocation key_where = location_of(key.source());
        if (key_where.line == 0) key_where = location_of(value.source());
        out.entries.push_back({std::string{key.str()}, key_where, convert(value)});
      }
      std::stable_sort(
          out.entries.begin(), out.entries.end(),
          [](const SceneEntry& a, const SceneEntry& b) { return before(a.where, b.where); });
      break;
    case toml::node_type::date:
      out.kind = SceneNode::Kind::other;
      out.string = "date";
      break;
    case toml::node_type::time:
      out.kind = SceneNode::Kind::other;
      out.string = "time";
      break;
    case toml::node_type::date_time:
      out.kind = SceneNode::Kind::other;
      out.string = "date-time";
      break;
    case toml::node_type::none:
      out.kind = SceneNode::Kind::other;
      out.string = "nothing";
      break;
  }
  return out;
}

}  // namespace

SceneNode parse_scene_document(std::string_view text, const std::string& source_name) {
  // toml++ 3.3.0 has undefined behaviour on some non-ASCII text (scene_ascii.h).
  if (const auto where = first_non_ascii_outside_comments(text)) {
    throw SceneError(scene_error_text(
        source_name, *where, "syntax error",
        "non-ASCII character outside a comment (keys and values are plain ASCII)"));
  }
  toml::table root;
  try {
    root = toml::parse(text, source_name);
  } catch (const toml::parse_error& e) {
    throw SceneError(
        scene_error_text(source_name, location_of(e.source()), "syntax error", e.description()));
  }
  SceneNode tree = convert(root);
  tree.where = {1, 1};
  return tree;
}

std::string kind_name(const SceneNode& node) {
  switch (node.kind) {
    case SceneNode::Kind::integer:
      return "integer";
    case SceneNode::Kind::floating:
      return "float";
    case SceneNode::Kind::boolean:
      return "boolean";
    case SceneNode::Kind::string:
      return "string";
    case SceneNode::Kind::array:
      return "array";
    case SceneNode::Kind::table:
      return "table";
    case SceneNode::Kind::other:
      break;
  }
  return node.string;
}

}  // namespace raintrace::cli
