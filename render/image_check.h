// Is an image file complete? POV-Ray may be killed while writing a PNG, so a file is trusted
// only after it decodes entirely at the expected size. OpenImageIO stays inside the .cpp.
#pragma once

#include <filesystem>
#include <string>

namespace raintrace::render {

/// True when path decodes completely with OpenImageIO and is width×height (any channel count).
/// Never throws; a reason for a false answer goes to *why when given.
bool image_is_complete(const std::filesystem::path& path, int width, int height,
                       std::string* why = nullptr);

}  // namespace raintrace::render
