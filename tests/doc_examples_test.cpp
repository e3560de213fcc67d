// Every example command of README.md and of raintrace's --help texts runs as written and
// succeeds. README's examples are its ```sh blocks that call raintrace, each run as one bash
// script; --help's are the lines that start with `raintrace ` or `cd ` (after "Example: ",
// without their # comment), each run on its own, in the order the help shows them.
//
// They run in a scratch folder laid out like the repository (tests/reference and scripts/ are
// links to the real ones) with raintrace on PATH. Its examples/ holds the example scenes with
// [output] at 32×18 pixels and 24 frames, so the commands run as written in seconds rather
// than the minutes a full render takes; what this checks is that every command line in the
// docs is valid, names files that exist, fits the commands before it, and exits 0. Examples
// that need Slurm run in the Slurm suite, each on a one-node cluster of its own
// (scripts/slurm-localhost.sh), when this runs as root.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/command.h"

namespace {

namespace fs = std::filesystem;

const fs::path kSourceDir = RAINTRACE_SOURCE_DIR;
const fs::path kBinary = RAINTRACE_BINARY;

struct Example {
  std::string where;   ///< "README.md line 120", "raintrace render --help"
  std::string script;  ///< bash
  bool slurm = false;  ///< needs a Slurm cluster
};

using raintrace::test_support::read_text;
using raintrace::test_support::run_command;

std::string trimmed(const std::string& line) {
  const std::size_t first = line.find_first_not_of(' ');
  const std::size_t last = line.find_last_not_of(' ');
  return first == std::string::npos ? "" : line.substr(first, last - first + 1);
}

bool needs_slurm(const std::string& script) {
  return script.find("--backend slurm") != std::string::npos ||
         script.find("slurm-localhost.sh") != std::string::npos;
}

/// README.md's ```sh blocks that call raintrace, in order.
std::vector<Example> readme_examples() {
  std::vector<Example> examples;
  std::istringstream in(read_text(kSourceDir / "README.md"));
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line != "```sh") continue;
    Example example{"README.md line " + std::to_string(number), "", false};
    bool calls_raintrace = false;
    while (std::getline(in, line) && line != "```") {
      ++number;
      calls_raintrace = calls_raintrace || line.rfind("raintrace ", 0) == 0;
      example.script += line + "\n";
    }
    ++number;
    example.slurm = needs_slurm(example.script);
    if (calls_raintrace) examples.push_back(example);
  }
  return examples;
}

/// The example lines of `raintrace [command] --help`, in order.
std::vector<Example> help_examples(const std::string& command) {
  const std::string where = "raintrace " + (command.empty() ? "" : command + " ") + "--help";
  std::vector<Example> examples;
  std::istringstream in(run_command("'" + kBinary.string() + "' " + command + " --help").output);
  for (std::string line; std::getline(in, line);) {
    std::string text = trimmed(line);
    if (text.rfind("Example: ", 0) == 0) text = text.substr(9);
    if (text.rfind("raintrace ", 0) != 0 && text.rfind("cd ", 0) != 0) continue;
    if (const std::size_t comment = text.find("  #"); comment != std::string::npos) {
      text = trimmed(text.substr(0, comment));
    }
    examples.push_back({where, text + "\n", needs_slurm(text)});
  }
  return examples;
}

/// Every example, the --help texts first (the main one, then each command's), then README.
std::vector<Example> all_examples() {
  std::vector<Example> all;
  for (const char* command : {"", "simulate", "export", "render", "compare"}) {
    for (Example& e : help_examples(command)) all.push_back(std::move(e));
  }
  for (Example& e : readme_examples()) all.push_back(std::move(e));
  return all;
}

/// An example scene with its [output] at 32×18 pixels and 24 frames, everything else as is.
std::string small_copy(const std::string& scene) {
  const std::string output = "width = 32\nheight = 18\nframes = 24\n";
  std::istringstream in(scene);
  std::string out;
  std::string section;
  bool written = false;
  for (std::string line; std::getline(in, line);) {
    const std::string text = trimmed(line);
    if (!text.empty() && text.front() == '[') section = text.substr(0, text.find(']') + 1);
    const std::string key = text.substr(0, text.find_first_of(" ="));
    if (section == "[output]" && (key == "width" || key == "height" || key == "frames")) continue;
    out += line + "\n";
    if (section == "[output]" && !written && !text.empty() && text.front() == '[') {
      out += output;
      written = true;
    }
  }
  return written ? out : out + "\n[output]\n" + output;
}

class DocExamples : public ::testing::Test {
 protected:
  /// The running test's scratch folder, this checkout's own.
  static fs::path work_folder() {
    return raintrace::test_support::checkout_scratch_folder(
        std::string{"raintrace_doc_examples_"} +
            ::testing::UnitTest::GetInstance()->current_test_info()->name(),
        kSourceDir);
  }

  void SetUp() override {
    if (std::system("command -v povray >/dev/null 2>&1") != 0) {
      GTEST_SKIP() << "POV-Ray is not installed: the render examples cannot run";
    }
    // One folder per test: ctest runs them as separate processes at the same time.
    m_work = work_folder();
    fs::remove_all(m_work);
    fs::create_directories(m_work / "examples");
    fs::create_directories(m_work / "tests");
    fs::create_directory_symlink(kSourceDir / "tests" / "reference",
                                 m_work / "tests" / "reference");
    fs::create_directory_symlink(kSourceDir / "scripts", m_work / "scripts");
    for (const auto& entry : fs::directory_iterator(kSourceDir / "examples")) {
      if (entry.path().extension() != ".toml") continue;
      std::ofstream(m_work / "examples" / entry.path().filename())
          << small_copy(read_text(entry.path()));
    }
  }

  /// Runs the example's script in the scratch folder; an empty string when it exits 0, else
  /// where it comes from, the script and the end of its output.
  std::string failure_of(const Example& example, int number) {
    const fs::path script = m_work / ("example_" + std::to_string(number) + ".sh");
    const fs::path log = m_work / ("example_" + std::to_string(number) + ".log");
    std::ofstream(script) << "set -e\n" << example.script;
    const std::string command = "cd '" + m_work.string() + "' && PATH='" +
                                kBinary.parent_path().string() + "':\"$PATH\" bash '" +
                                script.string() + "' >'" + log.string() + "' 2>&1";
    const int status = std::system(command.c_str());
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
    const std::string output = read_text(log);
    return example.where + ": exit " + std::to_string(WEXITSTATUS(status)) + "\n" + example.script +
           "--- output (" + log.string() + "), last lines:\n" +
           output.substr(output.size() > 1500 ? output.size() - 1500 : 0);
  }

  fs::path m_work;
};

TEST_F(DocExamples, EveryExampleRunsAsWritten) {
  const std::vector<Example> examples = all_examples();
  int run = 0;
  for (const Example& example : examples) {
    if (example.slurm) continue;
    EXPECT_EQ(failure_of(example, run), "");
    ++run;
  }
  // The help texts have about 20 examples and README two blocks: finding none means the
  // extraction broke, not that there is nothing to run.
  EXPECT_GE(run, 20);
}

TEST_F(DocExamples, FindsTheExamplesOfEveryHelpTextAndOfReadme) {
  const std::vector<Example> examples = all_examples();
  for (const char* where :
       {"raintrace --help", "raintrace simulate --help", "raintrace export --help",
        "raintrace render --help", "raintrace compare --help", "README.md"}) {
    const auto found = std::count_if(examples.begin(), examples.end(), [&](const Example& e) {
      return e.where.rfind(where, 0) == 0;
    });
    EXPECT_GE(found, 1) << "no example found in " << where;
  }
}

class SlurmDocExamples : public DocExamples {
 protected:
  void SetUp() override {
    // A run that was killed (a ctest timeout) leaves its clusters running: stop them first.
    const fs::path old = work_folder();
    if (fs::exists(old)) {
      for (const auto& entry : fs::directory_iterator(old)) {
        if (entry.path().filename().string().rfind("cluster_", 0) != 0) continue;
        run_command("'" + (kSourceDir / "scripts" / "slurm-localhost.sh").string() + "' stop '" +
                    entry.path().string() + "'");
      }
    }
    DocExamples::SetUp();
  }
};

TEST_F(SlurmDocExamples, EverySlurmExampleRunsAsWrittenOnAOneNodeCluster) {
  if (::geteuid() != 0 || std::system("command -v sbatch >/dev/null 2>&1") != 0) {
    GTEST_SKIP() << "needs root and Slurm (scripts/install-deps.sh --test) to start a cluster";
  }
  int run = 0;
  for (Example example : all_examples()) {
    if (!example.slurm) continue;
    // An example that does not start its own cluster gets one for itself.
    if (example.script.find("slurm-localhost.sh start") == std::string::npos) {
      const std::string cluster = (m_work / ("cluster_" + std::to_string(run))).string();
      example.script = "scripts/slurm-localhost.sh start '" + cluster + "' >/dev/null\n" +
                       "trap \"scripts/slurm-localhost.sh stop '" + cluster + "'\" EXIT\n" +
                       "export SLURM_CONF='" + cluster + "/slurm.conf'\n" + example.script;
    }
    EXPECT_EQ(failure_of(example, 100 + run), "");
    // A README block that starts a cluster stops it at its end; if it failed before, stop it.
    const std::string start = "slurm-localhost.sh start ";
    if (const std::size_t at = example.script.find(start); at != std::string::npos) {
      const std::size_t from = at + start.size();
      const std::string dir = example.script.substr(from, example.script.find('\n', from) - from);
      std::system(("cd '" + m_work.string() + "' && scripts/slurm-localhost.sh stop " + dir +
                   " >/dev/null 2>&1")
                      .c_str());
    }
    ++run;
  }
  EXPECT_GE(run, 2);
}

}  // namespace
