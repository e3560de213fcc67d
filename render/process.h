// A child process in its own process group, with its output going to a log file. render/ needs
// exactly this much: start POV-Ray (or ffmpeg, sbatch) without blocking, poll it, and stop it
// and everything it started when the user interrupts.
#pragma once

#include <sys/types.h>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace raintrace::render {

struct ProcessSpec {
  std::vector<std::string> argv;      ///< argv[0] is looked up in PATH when it has no slash
  std::filesystem::path working_dir;  ///< empty = inherit
  /// Variables set (or replaced) in the child's environment.
  std::map<std::string, std::string> env;
  /// stdout and stderr both go here (truncated first); empty = /dev/null.
  std::filesystem::path log_path;
};

/// A running child. Not copyable; the destructor kills and reaps a child still running, so an
/// exception never leaves a POV-Ray process behind.
class ChildProcess {
 public:
  /// Starts the child as the leader of a new process group. Throws std::system_error when fork
  /// fails; a program that cannot be executed makes the child exit with code 127.
  explicit ChildProcess(const ProcessSpec& spec);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  /// Non-blocking: the exit code once the child has ended (128 + signal when killed), else
  /// nullopt.
  std::optional<int> poll();
  /// Blocks until the child ends; returns its exit code as poll() does.
  int wait();
  /// Sends SIGTERM to the whole group, waits up to grace_seconds, then SIGKILL; reaps the child.
  void stop(double grace_seconds = 2.0);

  pid_t pid() const { return m_pid; }

 private:
  pid_t m_pid = -1;
  std::optional<int> m_exit_code;
};

/// Runs a command to the end and returns its exit code and captured stdout (stderr goes to the
/// log or /dev/null as in spec; spec.log_path is ignored for stdout).
struct CommandOutput {
  int exit_code = 0;
  std::string out;
};
CommandOutput run_capture(const ProcessSpec& spec);

/// Absolute path of an executable found in PATH, or nullopt.
std::optional<std::filesystem::path> find_program(const std::string& name);

/// The command line as a shell would accept it (quoted where needed), for error messages.
std::string shell_quote_command(const std::vector<std::string>& argv);

}  // namespace raintrace::render
