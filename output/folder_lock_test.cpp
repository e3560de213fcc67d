// One run per folder: a second lock fails at once naming the holder; the kernel releases a dead
// process's lock; Slurm tasks recognise the run they belong to.
#include "output/folder_lock.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "output/layout.h"
#include "output/test_dir.h"

namespace raintrace::output {
namespace {

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in{path, std::ios::binary};
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A child process that takes dir's lock, says so through a pipe, and waits to be killed.
class LockingChild {
 public:
  explicit LockingChild(const std::filesystem::path& dir) {
    int fds[2];
    if (::pipe(fds) != 0) throw std::runtime_error("pipe");
    m_pid = ::fork();
    if (m_pid == 0) {
      ::close(fds[0]);
      try {
        FolderLock lock{dir, "raintrace render child.toml -o out"};
        const char ok = 'y';
        [[maybe_unused]] auto n = ::write(fds[1], &ok, 1);
        for (;;) ::pause();
      } catch (...) {
        ::_exit(3);
      }
    }
    ::close(fds[1]);
    char c = 0;
    m_locked = ::read(fds[0], &c, 1) == 1 && c == 'y';
    ::close(fds[0]);
  }
  ~LockingChild() { kill_now(); }
  LockingChild(const LockingChild&) = delete;
  LockingChild& operator=(const LockingChild&) = delete;

  void kill_now() {
    if (m_pid <= 0) return;
    ::kill(m_pid, SIGKILL);
    int status = 0;
    ::waitpid(m_pid, &status, 0);
    m_pid = -1;
  }
  [[nodiscard]] pid_t pid() const { return m_pid; }
  [[nodiscard]] bool locked() const { return m_locked; }

 private:
  pid_t m_pid = -1;
  bool m_locked = false;
};

TEST(FolderLock, ASecondProcessIsRefusedAtOnceWithTheHolderNamed) {
  const auto dir = testing::fresh_test_dir("lock_two");
  LockingChild child{dir};
  ASSERT_TRUE(child.locked());
  try {
    FolderLock second{dir, "raintrace render other.toml -o out"};
    FAIL() << "the second lock was granted";
  } catch (const FolderBusy& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(dir.string() + " is in use by another raintrace"), std::string::npos)
        << what;
    EXPECT_NE(what.find("pid " + std::to_string(child.pid())), std::string::npos) << what;
    EXPECT_NE(what.find("raintrace render child.toml -o out"), std::string::npos) << what;
    EXPECT_NE(what.find(" on host "), std::string::npos) << what;
    EXPECT_NE(what.find(" since 20"), std::string::npos) << what;
  }
  // kill -9: the kernel releases the lock, and the next run gets the folder.
  child.kill_now();
  FolderLock next{dir, "raintrace render next.toml -o out"};
  EXPECT_EQ(next.holder().pid, static_cast<long>(::getpid()));
}

TEST(FolderLock, TwoLocksInOneProcessConflictToo) {
  // Open-file-description locks belong to the open file, not the process: a second claim of
  // the same folder from the same program is refused just the same.
  const auto dir = testing::fresh_test_dir("lock_same");
  FolderLock first{dir, "first"};
  EXPECT_THROW(FolderLock(dir, "second"), FolderBusy);
}

TEST(FolderLock, ReleasedLockFileIsEmptyAndFreeAgain) {
  const auto dir = testing::fresh_test_dir("lock_release");
  std::string run_id;
  {
    FolderLock lock{dir, "one"};
    run_id = lock.holder().run_id;
    EXPECT_EQ(run_id.size(), 16U);
    EXPECT_NE(read_text(dir / kLockFile).find(run_id), std::string::npos);
    const auto holder = lock_holder(dir);
    ASSERT_TRUE(holder);
    EXPECT_EQ(holder->run_id, run_id);
    EXPECT_EQ(holder->command, "one");
  }
  EXPECT_TRUE(read_text(dir / kLockFile).empty());
  EXPECT_FALSE(lock_holder(dir));
  FolderLock again{dir, "two"};
  EXPECT_NE(again.holder().run_id, run_id);  // every run has its own id
}

TEST(FolderLock, ATaskWorksOnlyUnderTheRunThatSubmittedIt) {
  const auto dir = testing::fresh_test_dir("lock_task");
  LockingChild child{dir};
  ASSERT_TRUE(child.locked());
  const auto holder = lock_holder(dir);
  ASSERT_TRUE(holder);
  EXPECT_NO_THROW(require_lock_held_by(dir, holder->run_id));
  EXPECT_THROW(require_lock_held_by(dir, "0000000000000000"), std::runtime_error);
  // The submitting run died (its record is still in the file): the task must not go on.
  child.kill_now();
  try {
    require_lock_held_by(dir, holder->run_id);
    FAIL() << "a task worked for a dead run";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string{e.what()}.find("nobody holds it"), std::string::npos) << e.what();
  }
}

TEST(FolderLock, AVeryLongCommandIsCutInTheRecord) {
  const auto dir = testing::fresh_test_dir("lock_long");
  FolderLock lock{dir, "raintrace render " + std::string(100000, 'x')};
  EXPECT_LT(lock.holder().command.size(), 400U);
  EXPECT_LT(read_text(dir / kLockFile).size(), 1000U);
}

}  // namespace
}  // namespace raintrace::output
