// ChildProcess: exit codes, logs, and stopping a whole process group.
#include "render/process.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>
#include <csignal>
#include <fstream>
#include <sstream>
#include <thread>

#include "render/test_folder.h"

namespace raintrace::render {
namespace {

std::string read_all(const std::filesystem::path& p) {
  std::ifstream in{p};
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ChildProcess, ReportsExitCodeAndWritesBothStreamsToTheLog) {
  const auto dir = testing::fresh_test_dir("exit");
  ProcessSpec spec;
  spec.argv = {"sh", "-c", "echo out; echo err >&2; echo $FOO; pwd; exit 3"};
  spec.working_dir = dir;
  spec.env = {{"FOO", "bar"}};
  spec.log_path = dir / "log.txt";
  ChildProcess child{spec};
  EXPECT_EQ(child.wait(), 3);
  const std::string log = read_all(dir / "log.txt");
  EXPECT_NE(log.find("out\n"), std::string::npos);
  EXPECT_NE(log.find("err\n"), std::string::npos);
  EXPECT_NE(log.find("bar\n"), std::string::npos);
  EXPECT_NE(log.find(dir.string()), std::string::npos);
}

TEST(ChildProcess, MissingProgramExitsWith127) {
  ProcessSpec spec;
  spec.argv = {"/nonexistent/raintrace-no-such-program"};
  ChildProcess child{spec};
  EXPECT_EQ(child.wait(), 127);
}

// A process that is gone or a zombie (killed, waiting for init to reap it) is not running.
bool is_running(pid_t pid) {
  std::ifstream stat{"/proc/" + std::to_string(pid) + "/stat"};
  std::string line;
  if (!std::getline(stat, line)) return false;
  const auto close = line.rfind(')');
  return close != std::string::npos && close + 2 < line.size() && line[close + 2] != 'Z';
}

TEST(ChildProcess, StopKillsTheWholeGroupIncludingGrandchildren) {
  const auto dir = testing::fresh_test_dir("stop");
  ProcessSpec spec;
  // The shell ignores SIGTERM, so stop() must escalate; its background sleep is a grandchild.
  spec.argv = {"sh", "-c", "trap '' TERM; sleep 30 & echo $! > grandchild; wait"};
  spec.working_dir = dir;
  ChildProcess child{spec};
  pid_t grandchild = 0;
  for (int i = 0; i < 100 && grandchild == 0; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    std::ifstream{dir / "grandchild"} >> grandchild;
  }
  ASSERT_GT(grandchild, 0);
  ASSERT_TRUE(is_running(grandchild));
  child.stop(0.3);
  EXPECT_TRUE(child.poll().has_value());
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_FALSE(is_running(grandchild));  // no POV-Ray outlives an interrupted render
}

TEST(ChildProcess, DiesWithItsParent) {
  const auto dir = testing::fresh_test_dir("orphan");
  // An intermediate process starts the child through ChildProcess, then is SIGKILLed the way a
  // user might kill raintrace; the grandchild (a stand-in for POV-Ray) must not live on.
  const pid_t middle = ::fork();
  ASSERT_GE(middle, 0);
  if (middle == 0) {
    ProcessSpec spec;
    spec.argv = {"sh", "-c", "echo $$ > child; exec sleep 30"};
    spec.working_dir = dir;
    ChildProcess child{spec};
    ::pause();
    ::_exit(0);
  }
  pid_t child = 0;
  for (int i = 0; i < 100 && child == 0; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    std::ifstream{dir / "child"} >> child;
  }
  ASSERT_GT(child, 0);
  ASSERT_TRUE(is_running(child));
  ::kill(middle, SIGKILL);
  ::waitpid(middle, nullptr, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  EXPECT_FALSE(is_running(child));
}

TEST(RunCapture, ReturnsStdoutAndExitCode) {
  ProcessSpec spec;
  spec.argv = {"sh", "-c", "printf 'a b\\n'; exit 4"};
  const auto r = run_capture(spec);
  EXPECT_EQ(r.exit_code, 4);
  EXPECT_EQ(r.out, "a b\n");
}

TEST(FindProgram, FindsShAndNotNonsense) {
  ASSERT_TRUE(find_program("sh").has_value());
  EXPECT_TRUE(find_program("sh")->is_absolute());
  EXPECT_FALSE(find_program("raintrace-no-such-program-xyz").has_value());
}

TEST(ShellQuote, QuotesOnlyWhatNeedsIt) {
  EXPECT_EQ(shell_quote_command({"povray", "+SF3", "a b", "it's"}), "povray +SF3 'a b' 'it'\\''s'");
}

}  // namespace
}  // namespace raintrace::render
