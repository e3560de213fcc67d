// A scene file, loaded and validated: the one place the TOML is read (toml++ stays in the .cpp).
// Every value is checked; errors name file:line:column and the key.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

#include "povgen/export_params.h"
#include "sim/param_table.h"
#include "sim/params.h"

namespace raintrace::cli {

/// A problem in a scene file. what() is one line: "FILE:LINE:COL: KEY: message".
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Scene {
  std::filesystem::path source;  ///< the scene file (or the name given to load_scene_string)
  std::string text;              ///< the file's bytes, for hashing into manifest.json
  /// Folder that look.environment.include_path is relative to: the scene file's folder (or the
  /// base_dir given to load_scene_string). Added by the cli owner.
  std::filesystem::path base_dir;
  int frames = 48;     ///< length of the animation
  sim::SimParams sim;  ///< camera is filled identically in sim and look
  povgen::ExportParams look;
};

/// Scene's own key; the others are in the tables of sim/ and povgen/ (scene_tables.h).
inline constexpr sim::Param<Scene> kSceneParams[] = {
    sim::integer("output", "frames", &Scene::frames, "frames", 1, 100000),
};

/// Reads and validates a scene file. Throws SceneError (also for a missing/unreadable file).
Scene load_scene_file(const std::filesystem::path& path);

/// Same from text; source_name is used in messages, base_dir resolves [environment] include.
Scene load_scene_string(std::string_view toml_text, const std::string& source_name,
                        const std::filesystem::path& base_dir);

struct FrameRange {
  int first = 1;  ///< 1-based, inclusive
  int last = 1;   ///< inclusive
};

/// Parses "--frames A-B" (or "N") against a scene of `frames` frames; empty = all frames.
/// Throws std::invalid_argument with a clear message when out of range or malformed.
FrameRange parse_frame_range(std::string_view text, int frames);

}  // namespace raintrace::cli
