// Frames on disk: reading a rendered HDR frame, writing a developed picture. OpenImageIO stays in
// the .cpp.
#pragma once

#include <filesystem>
#include <string>

#include "film/rgb_image.h"

namespace raintrace::film {

/// Reads the first subimage of any file OpenImageIO reads (POV-Ray's half-float OpenEXR, also
/// PNG, HDR, TIFF), as float: the first three channels as R, G, B (a one- or two-channel image
/// is grey: its first channel three times); further channels (alpha) are ignored. Values are as
/// stored: scene-linear for EXR and HDR. Throws std::runtime_error naming the file and
/// OpenImageIO's reason when it cannot be read.
RgbImage read_rgb_image(const std::filesystem::path& path);

/// Writes a display-encoded picture as an 8-bit sRGB PNG: each value clamped to [0, 1], times
/// 255, rounded to the nearest integer. `description` goes into the PNG's Description text
/// (e.g. the develop settings). zlib level 1 (fast; rendered frames barely compress better at
/// higher levels). Written under a temporary name in the same folder and renamed,
/// so a reader never sees half a file. Throws std::runtime_error naming the file on failure.
void write_png(const std::filesystem::path& path, const RgbImage& image,
               const std::string& description = "");

}  // namespace raintrace::film
