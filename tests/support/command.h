// Helpers the end-to-end tests share: a file's text, and a shell command's output and exit
// code. Header-only, for test programs only.
#pragma once

#include <sys/wait.h>
#include <unistd.h>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

namespace raintrace::test_support {

/// The bytes of a file ("" when it cannot be read).
inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

struct CommandResult {
  int exit_code = -1;  ///< -1 when the command could not run or was killed
  std::string output;  ///< stdout and stderr together
};

/// Runs `command` with /bin/sh, stderr sent to stdout, and waits for it.
inline CommandResult run_command(const std::string& command) {
  CommandResult result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe) != nullptr) {
    result.output += buffer.data();
  }
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

/// A folder of the temporary directory named after `name` and the source tree the tests were
/// built from: the same on every run of one checkout (a test may clean up what a killed run
/// left), different for two checkouts, whose test suites may run on one machine at once.
inline std::filesystem::path checkout_scratch_folder(const std::string& name,
                                                     const std::filesystem::path& source_dir) {
  const std::size_t tree = std::hash<std::string>{}(source_dir.string());
  std::ostringstream folder;
  folder << name << '_' << std::hex << (tree & 0xffffffffu);
  return std::filesystem::temp_directory_path() / folder.str();
}

/// A file or folder of the temporary directory named after `name` and this test process (the
/// process's number goes before the extension, which says what a file holds): two test suites
/// running at once (two checkouts, or a build's tests beside a fresh clone's) never share it.
/// For tests that remove what they make.
inline std::filesystem::path process_scratch_path(const std::string& name) {
  const std::filesystem::path path{name};
  return std::filesystem::temp_directory_path() / path.parent_path() /
         (path.stem().string() + '_' + std::to_string(::getpid()) + path.extension().string());
}

}  // namespace raintrace::test_support
