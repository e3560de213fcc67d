// Test helper: a fresh empty folder under the system temp dir, per test and process.
#pragma once

#include <unistd.h>
#include <filesystem>
#include <string>

namespace raintrace::output::testing {

inline std::filesystem::path fresh_test_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("raintrace_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace raintrace::output::testing
