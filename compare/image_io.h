// Reading and writing images through OpenImageIO (any format it reads), kept behind plain
// functions so nothing else in raintrace includes OpenImageIO headers.
#pragma once

#include <filesystem>

#include "compare/image.h"

namespace raintrace::compare {

/// Reads the first subimage of any file OpenImageIO can read, converted to float. Throws
/// std::runtime_error naming the file and OpenImageIO's reason when it cannot be read.
Image read_image(const std::filesystem::path& path);

/// Writes an image; the format follows the extension (".png" → 8-bit PNG, values clamped to
/// [0, 1] and rounded). Writes to a temporary name and renames, so a reader never sees half a
/// file. Throws std::runtime_error naming the file on failure.
void write_image(const std::filesystem::path& path, const Image& image);

/// True when OpenImageIO knows the file's extension (case-insensitive) as a format it reads.
bool is_image_file(const std::filesystem::path& path);

/// Limits OpenImageIO's own worker threads (its global "threads" attribute), so a pool of our
/// threads over frames does not oversubscribe the cores. 0 = OpenImageIO's default.
void set_oiio_threads(int threads);

}  // namespace raintrace::compare
