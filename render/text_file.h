// Reading a small text file the render pipeline may not have written yet (a log, a hash stamp, a
// cluster job's result): its bytes, or nothing.
#pragma once

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

}  // namespace raintrace::render
