// fork/exec with a process group per child, so stopping a render also stops anything the
// child started, and a Ctrl-C in the terminal reaches only raintrace (which then stops children
// itself and keeps what is finished).
#include "render/process.h"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <system_error>
#include <thread>

namespace raintrace::render {
namespace {

int decode_status(int status) {
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return 255;
}

// Everything the child needs is prepared before fork: after fork only async-signal-safe calls.
struct PreparedExec {
  std::vector<std::string> args;
  std::vector<char*> argv;
  std::vector<std::string> env_strings;
  std::vector<char*> envp;
};

PreparedExec prepare(const ProcessSpec& spec) {
  PreparedExec p;
  p.args = spec.argv;
  if (!p.args.empty() && p.args[0].find('/') == std::string::npos) {
    if (auto found = find_program(p.args[0])) p.args[0] = found->string();
  }
  for (auto& a : p.args) p.argv.push_back(a.data());
  p.argv.push_back(nullptr);
  std::map<std::string, std::string> env;
  for (char** e = environ; *e != nullptr; ++e) {
    std::string kv{*e};
    const auto eq = kv.find('=');
    if (eq != std::string::npos) env[kv.substr(0, eq)] = kv.substr(eq + 1);
  }
  for (const auto& [k, v] : spec.env) env[k] = v;
  for (const auto& [k, v] : env) p.env_strings.push_back(k + "=" + v);
  for (auto& s : p.env_strings) p.envp.push_back(s.data());
  p.envp.push_back(nullptr);
  return p;
}

pid_t spawn(const ProcessSpec& spec, int stdout_fd) {
  if (spec.argv.empty()) throw std::invalid_argument("ChildProcess: empty command");
  PreparedExec p = prepare(spec);
  const std::string log = spec.log_path.empty() ? "/dev/null" : spec.log_path.string();
  const std::string dir = spec.working_dir.string();
  const int log_fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (log_fd < 0) {
    throw std::system_error(errno, std::generic_category(), "cannot open log " + log);
  }
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(log_fd);
    throw std::system_error(errno, std::generic_category(), "fork");
  }
  if (pid == 0) {
    ::setpgid(0, 0);
    // Children live in their own group (a terminal's Ctrl-C reaches only raintrace), so they
    // would survive a SIGKILL of raintrace: have the kernel kill them when the parent dies.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);
    // The parent may block these for its own handling; a child starts with defaults.
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, nullptr);
    ::signal(SIGINT, SIG_DFL);
    ::signal(SIGTERM, SIG_DFL);
    const int null_in = ::open("/dev/null", O_RDONLY);
    if (null_in >= 0) ::dup2(null_in, 0);
    ::dup2(stdout_fd >= 0 ? stdout_fd : log_fd, 1);
    ::dup2(log_fd, 2);
    if (!dir.empty() && ::chdir(dir.c_str()) != 0) ::_exit(127);
    ::execve(p.argv[0], p.argv.data(), p.envp.data());
    ::_exit(127);
  }
  // Also from the parent, so a stop() right after start never races the child's own setpgid.
  ::setpgid(pid, pid);
  ::close(log_fd);
  return pid;
}

}  // namespace

ChildProcess::ChildProcess(const ProcessSpec& spec) : m_pid(spawn(spec, -1)) {}

ChildProcess::~ChildProcess() {
  if (!m_exit_code) stop(0.5);
}

std::optional<int> ChildProcess::poll() {
  if (m_exit_code) return m_exit_code;
  int status = 0;
  const pid_t r = ::waitpid(m_pid, &status, WNOHANG);
  if (r == m_pid) m_exit_code = decode_status(status);
  if (r < 0 && errno == ECHILD) m_exit_code = 255;
  return m_exit_code;
}

int ChildProcess::wait() {
  while (!m_exit_code) {
    int status = 0;
    const pid_t r = ::waitpid(m_pid, &status, 0);
    if (r == m_pid) m_exit_code = decode_status(status);
    if (r < 0 && errno != EINTR) m_exit_code = 255;
  }
  return *m_exit_code;
}

void ChildProcess::stop(double grace_seconds) {
  if (poll()) return;
  ::kill(-m_pid, SIGTERM);
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(grace_seconds);
  while (!poll() && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (!poll()) {
    ::kill(-m_pid, SIGKILL);
    wait();
  }
  // Grandchildren that ignored SIGTERM still share the group: make sure nothing lingers.
  ::kill(-m_pid, SIGKILL);
}

CommandOutput run_capture(const ProcessSpec& spec) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw std::system_error(errno, std::generic_category(), "pipe");
  pid_t pid = -1;
  try {
    pid = spawn(spec, fds[1]);
  } catch (...) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw;
  }
  ::close(fds[1]);
  CommandOutput result;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n > 0) {
      result.out.append(buffer, static_cast<std::size_t>(n));
    } else if (n == 0 || errno != EINTR) {
      break;
    }
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  result.exit_code = decode_status(status);
  return result;
}

std::optional<std::filesystem::path> find_program(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::string_view rest = path != nullptr ? path : "/usr/local/bin:/usr/bin:/bin";
  while (!rest.empty()) {
    const auto colon = rest.find(':');
    const std::string dir{rest.substr(0, colon)};
    rest = colon == std::string_view::npos ? std::string_view{} : rest.substr(colon + 1);
    if (dir.empty()) continue;
    const std::filesystem::path candidate = std::filesystem::path{dir} / name;
    if (::access(candidate.c_str(), X_OK) == 0 && !std::filesystem::is_directory(candidate)) {
      return candidate;
    }
  }
  return std::nullopt;
}

std::string shell_quote_command(const std::vector<std::string>& argv) {
  std::string out;
  for (const auto& arg : argv) {
    if (!out.empty()) out += ' ';
    const bool plain = !arg.empty() && arg.find_first_not_of(
                                           "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                           "0123456789+-_=./:,@%") == std::string::npos;
    if (plain) {
      out += arg;
      continue;
    }
    out += '\'';
    for (char c : arg) {
      if (c == '\'') {
        out += "'\\''";
      } else {
        out += c;
      }
    }
    out += '\'';
  }
  return out;
}

}  // namespace raintrace::render
