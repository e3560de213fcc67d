// Test helper: a fresh empty folder under the system temp dir, per test and process.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "tests/support/command.h"

namespace raintrace::output::testing {

/// The folders fresh_test_dir() made in this process. They are removed when the process ends if
/// its tests passed; a failed test's are kept to look into. (Every full test run left ~50 of
/// them behind, up to 41 MB each: 3.4 GB in the temporary directory after a few days' work.)
class TestDirs {
 public:
  static TestDirs& made() {
    static TestDirs dirs;
    return dirs;
  }
  void add(const std::filesystem::path& dir) { m_dirs.push_back(dir); }
  ~TestDirs() {
    // Only the process that made them: a forked child that ends must not take its parent's.
    if (::getpid() != m_owner || !::testing::UnitTest::GetInstance()->Passed()) return;
    std::error_code ignored;
    for (const auto& dir : m_dirs) std::filesystem::remove_all(dir, ignored);
  }
  TestDirs(const TestDirs&) = delete;
  TestDirs& operator=(const TestDirs&) = delete;

 private:
  TestDirs() = default;
  pid_t m_owner = ::getpid();
  std::vector<std::filesystem::path> m_dirs;
};

inline std::filesystem::path fresh_test_dir(const std::string& name) {
  const auto dir = raintrace::test_support::process_scratch_path("raintrace_test_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  TestDirs::made().add(dir);
  return dir;
}

}  // namespace raintrace::output::testing
