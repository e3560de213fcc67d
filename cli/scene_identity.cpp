// The scene's canonical form: what decides whether an output folder holds this scene's frames.
// A folder used to be tied to the scene file's bytes, so a comment, or a develop-only key such
// as exposure_ev, made it "another scene"; the loaded values decide instead. Keys at their
// built-in defaults are left out too: a later raintrace that adds a key adds no line for the
// scenes that do not set it, so their folders stay theirs and their finished frames are kept
// (the frames' own input hashes still catch any change to what POV-Ray reads).
#include <fmt/core.h>
#include <set>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "cli/scene.h"
#include "cli/scene_tables.h"

namespace raintrace::cli {
namespace {

/// Keys that do not change a rendered frame, or that FolderIdentity holds as fields of their own
/// (so a refusal can say "size 640x360 there, 320x240 here" instead of "another scene").
constexpr std::string_view kLeftOut[] = {
    "seed",           // FolderIdentity::seed
    "output.frames",  // frame n is the same whatever follows it: the folder grows or shrinks
    "output.width",  "output.height", "output.fps", "output.quality",  // FolderIdentity
    "export.mask",                                                     // FolderIdentity::masks
};

bool left_out(std::string_view full_key) {
  for (const std::string_view key : kLeftOut) {
    if (key == full_key) return true;
  }
  return false;
}

template <class P>
std::string value_text(const sim::Param<P>& row, const P& object) {
  return std::visit(
      [&](const auto& field) -> std::string {
        using Field = std::decay_t<decltype(field)>;
        if constexpr (std::is_same_v<Field, sim::ChoiceField<P>>) {
          const std::size_t i = field.get(object, field.names);
          return i < field.names.size() ? std::string{field.names[i]} : "?";
        } else if constexpr (std::is_same_v<Field, glm::dvec3 P::*>) {
          const glm::dvec3& v = object.*field;
          return fmt::format("[{}, {}, {}]", v.x, v.y, v.z);
        } else if constexpr (std::is_same_v<Field, std::string P::*>) {
          // Length first: no string can pass for another key's line.
          return fmt::format("{}:{}", (object.*field).size(), object.*field);
        } else {
          return fmt::format("{}", object.*field);  // shortest exact form for doubles
        }
      },
      row.field);
}

/// Every `section.key=value` line of scene's tables that can shape a rendered frame, in the
/// tables' order.
std::vector<std::string> key_lines(const Scene& scene) {
  std::vector<std::string> lines;
  for_each_table(scene, [&](auto table, const auto& object) {
    using P = std::remove_cvref_t<decltype(object)>;
    if constexpr (std::is_same_v<P, film::DevelopSettings>) {
      return;  // develop keys: changing them re-develops, never re-renders
    } else {
      for (const sim::Param<P>& row : table) {
        const std::string key = sim::full_key(row.section, row.key);
        if (!left_out(key)) lines.push_back(key + "=" + value_text(row, object));
      }
    }
  });
  return lines;
}

}  // namespace

std::string canonical_scene_text(const Scene& scene) {
  const std::vector<std::string> defaults = key_lines(Scene{});
  const std::set<std::string> at_default(defaults.begin(), defaults.end());
  std::string text = "raintrace scene, canonical form 2\n";
  for (const std::string& line : key_lines(scene)) {
    if (at_default.count(line) == 0) text += line + "\n";
  }
  return text;
}

}  // namespace raintrace::cli
