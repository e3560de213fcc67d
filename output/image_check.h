// Is an image file what it should be? POV-Ray may be killed while writing a PNG, and a user or
// a disk may change a file later, so an image counts as finished only after it decodes entirely
// at the expected size (image_is_complete, when it is made) and, from then on, while its bytes
// are the ones recorded (file_facts: size and content hash). OpenImageIO stays inside the .cpp.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace raintrace::output {

/// True when path decodes completely with OpenImageIO and is width×height (any channel count).
/// Never throws; a reason for a false answer goes to *why when given.
bool image_is_complete(const std::filesystem::path& path, int width, int height,
                       std::string* why = nullptr);

/// What a file's bytes are: their number and povgen::content_hash.
struct FileFacts {
  std::uint64_t size = 0;
  std::string hash;
  bool operator==(const FileFacts&) const = default;
};

/// The facts of a regular file; nullopt when there is none at path. Throws std::system_error
/// when it exists but cannot be read.
std::optional<FileFacts> file_facts(const std::filesystem::path& path);

}  // namespace raintrace::output
