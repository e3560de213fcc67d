// Part (c) of scene generation: text → files in the output folder. Thin: every file is written
// under a temporary name and renamed, so a crash never leaves a half-written scene behind.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "povgen/export_params.h"
#include "povgen/frame_values.h"

namespace raintrace::povgen {

/// Writes bytes to path via path + ".tmp" and a rename. Throws std::system_error naming the path
/// with the system's reason ("No space left on device"); no temporary file is left behind.
void write_file_atomic(const std::filesystem::path& path, std::string_view bytes);

/// Creates out_dir with frames/, textures/ and images/ (empty, for POV-Ray: a missing output
/// folder fails only after the whole parse). Throws std::system_error naming the folder.
void create_output_folders(const std::filesystem::path& out_dir);

/// Writes everything frames share: scene.inc, scene.pov, scene.ini, environment.inc,
/// raintrace_materials.inc, textures/streak_atlas.png, and mask.pov + mask.ini when
/// look.mask. scene_dir resolves a user's environment include. Returns the hash of all of
/// these files' bytes: a frame's input hash combines it with the frame's own text.
std::string write_shared_files(const std::filesystem::path& out_dir, const ExportParams& look,
                               int frame_count, const std::filesystem::path& scene_dir);

/// Streams the frame's text into path (via path.tmp and a rename) with `threads` writer
/// threads and returns content_hash(hash_prefix + text): the frame's input hash when
/// hash_prefix is the shared files' hash. Throws std::system_error naming the path.
std::string write_frame_file(const std::filesystem::path& path, const FrameValues& values,
                             std::string_view hash_prefix, int threads);

/// Bytes of a file, for hashing. Throws std::system_error if it cannot be read.
std::string read_file_bytes(const std::filesystem::path& path);

}  // namespace raintrace::povgen
