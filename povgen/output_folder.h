// Part (c) of scene generation: text → files in the output folder. Thin: every file is written
// under a temporary name and renamed, so a crash never leaves a half-written scene behind.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "povgen/export_params.h"

namespace raintrace::povgen {

/// Writes bytes to dir/relative via relative + ".tmp" and a rename. Throws std::runtime_error
/// naming the path.
void write_file_atomic(const std::filesystem::path& path, std::string_view bytes);

/// Creates out_dir with frames/, textures/ and images/ (empty, for POV-Ray: a missing output
/// folder fails only after the whole parse). Throws std::runtime_error naming the folder.
void create_output_folders(const std::filesystem::path& out_dir);

/// Writes everything frames share: scene.inc, scene.pov, scene.ini, environment.inc,
/// raintrace_materials.inc, textures/streak_atlas.png, and mask.pov + mask.ini when
/// look.mask. scene_dir resolves a user's environment include. Returns the hash of all of
/// these files' bytes: a frame's input hash combines it with the frame's own text.
std::string write_shared_files(const std::filesystem::path& out_dir, const ExportParams& look,
                               int frame_count, const std::filesystem::path& scene_dir);

/// Bytes of a file, for hashing. Throws std::runtime_error if it cannot be read.
std::string read_file_bytes(const std::filesystem::path& path);

}  // namespace raintrace::povgen
