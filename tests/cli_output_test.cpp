// Whole-output tests of the `raintrace` command, the way OpenImageIO's testsuite compares a
// tool's output with ref/out.txt: every command of tests/cli_output/commands.txt runs from the
// repository's folder, and its stdout, stderr and exit code, written one after the other, must
// equal tests/cli_output/out.txt byte for byte. So every --help text and error line is reviewed
// as the user sees it, and a change to one shows up in `git diff`.
//
// The reference changes only on purpose: `cmake --build build --target update-cli-output` runs
// this test with RAINTRACE_UPDATE_CLI_OUTPUT=1, which writes out.txt instead of comparing.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/command.h"

namespace {

namespace fs = std::filesystem;

const fs::path kSourceDir = RAINTRACE_SOURCE_DIR;
const fs::path kCases = kSourceDir / "tests" / "cli_output";

using raintrace::test_support::read_text;

/// The command lines of commands.txt (blank lines and # comments left out).
std::vector<std::string> commands() {
  std::vector<std::string> lines;
  std::istringstream in(read_text(kCases / "commands.txt"));
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.front() != '#') lines.push_back(line);
  }
  return lines;
}

/// Runs one command line ("raintrace ARGS") from the source folder and writes what a user
/// would see: "$ COMMAND", then "[stdout]" and "[stderr]" with their text when there is any,
/// then "[exit N]".
std::string run(const std::string& command, const fs::path& work) {
  const std::string args =
      command.substr(command.find(' ') == std::string::npos ? command.size() : command.find(' '));
  const std::string shell = "cd '" + kSourceDir.string() + "' && '" RAINTRACE_BINARY "'" + args +
                            " >'" + (work / "stdout").string() + "' 2>'" +
                            (work / "stderr").string() + "'";
  const int status = std::system(shell.c_str());
  const int exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::string out = "$ " + command + "\n";
  for (const char* stream : {"stdout", "stderr"}) {
    const std::string text = read_text(work / stream);
    if (text.empty()) continue;
    out += std::string{"["} + stream + "]\n" + text;
    if (text.back() != '\n') out += "\n";
  }
  return out + "[exit " + std::to_string(exit_code) + "]\n\n";
}

TEST(CliOutput, EveryCommandPrintsWhatOutTxtSays) {
  const fs::path work =
      raintrace::test_support::checkout_scratch_folder("raintrace_cli_output", kSourceDir);
  fs::create_directories(work);
  std::string actual;
  for (const std::string& command : commands()) actual += run(command, work);
  ASSERT_FALSE(actual.empty()) << "no commands in " << kCases / "commands.txt";
  // Nothing may have been written into the source tree.
  EXPECT_FALSE(fs::exists(kSourceDir / "out" / "x")) << "a command wrote out/x";

  const fs::path reference = kCases / "out.txt";
  if (std::getenv("RAINTRACE_UPDATE_CLI_OUTPUT") != nullptr) {
    std::ofstream(reference, std::ios::binary | std::ios::trunc) << actual;
    std::printf("wrote %s: review it with git diff before committing\n", reference.c_str());
    return;
  }
  std::ofstream(work / "out.txt", std::ios::binary | std::ios::trunc) << actual;
  const std::string expected = read_text(reference);
  if (actual == expected) return;
  std::istringstream a(expected), b(actual);
  std::string line_a, line_b;
  int line = 1;
  while (std::getline(a, line_a) && std::getline(b, line_b) && line_a == line_b) ++line;
  ADD_FAILURE() << "tests/cli_output/out.txt line " << line << " differs:\n  expected: " << line_a
                << "\n  actual:   " << line_b << "\nWhole output: " << work / "out.txt"
                << " (diff it with out.txt). If the change is intended: cmake --build build "
                << "--target update-cli-output, and review.";
}

}  // namespace
