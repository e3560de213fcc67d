// Reading a small text file the render pipeline may not have written yet (a log, a hash stamp, a
// cluster job's result): its bytes, or nothing.
#pragma once

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace raintrace::render {

/// The bytes of the file at `path`, or "" when it does not exist or cannot be read.
inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in{path, std::ios::binary};
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The last `bytes` bytes of the file at `path` (all of it if shorter), or "" as read_text: a
/// log that grows while POV-Ray runs is read from its end, not whole, each time it is looked at.
inline std::string read_tail(const std::filesystem::path& path, std::size_t bytes) {
  std::ifstream in{path, std::ios::binary | std::ios::ate};
  if (!in) return {};
  const std::streamoff size = in.tellg();
  const std::streamoff from =
      std::max<std::streamoff>(size - static_cast<std::streamoff>(bytes), 0);
  in.seekg(from);
  std::string tail(static_cast<std::size_t>(size - from), '\0');
  in.read(tail.data(), static_cast<std::streamsize>(tail.size()));
  tail.resize(static_cast<std::size_t>(in.gcount()));
  return tail;
}

}  // namespace raintrace::render
