// The folder lock: fcntl open-file-description locks on OUT/raintrace.lock, the holder's record
// as a line of JSON inside it.
#include "output/folder_lock.h"

#include <fcntl.h>
#include <fmt/core.h>
#include <unistd.h>
#include <cerrno>
#include <chrono>
#include <ctime>
#include <nlohmann/json.hpp>
#include <random>
#include <system_error>
#include <thread>

#include "output/layout.h"

namespace raintrace::output {
namespace {

constexpr std::size_t kMaxCommand = 300;

flock whole_file(short type) {
  flock lock{};
  lock.l_type = type;
  lock.l_whence = SEEK_SET;
  lock.l_start = 0;
  lock.l_len = 0;  // to the end, however long the file grows
  lock.l_pid = 0;  // required by F_OFD_*
  return lock;
}

std::string utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&now, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

std::string host_name() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "?";
  return name;
}

std::string random_run_id() {
  std::random_device device;  // getrandom() on Linux
  const std::uint64_t high = device(), low = device();
  return fmt::format("{:016x}", (high << 32) ^ low);
}

std::string read_all(int fd) {
  std::string text;
  char buffer[4096];
  off_t offset = 0;
  for (;;) {
    const ssize_t n = ::pread(fd, buffer, sizeof buffer, offset);
    if (n <= 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
    offset += n;
    if (text.size() > 65536) break;  // a record is a few hundred bytes; never read a huge file
  }
  return text;
}

std::optional<LockHolder> parse_holder(const std::string& text) {
  const auto doc = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (!doc.is_object()) return std::nullopt;
  LockHolder h;
  h.pid = doc.value("pid", 0L);
  h.host = doc.value("host", std::string{});
  h.command = doc.value("command", std::string{});
  h.since = doc.value("since", std::string{});
  h.run_id = doc.value("run_id", std::string{});
  return h;
}

// The record of whoever holds fd's lock. It is written just after the lock is taken, so a
// moment after a busy lock is found the record may not be there yet: look again briefly.
std::optional<LockHolder> read_holder_record(int fd) {
  for (int attempt = 0; attempt < 20; ++attempt) {
    if (auto holder = parse_holder(read_all(fd))) return holder;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return std::nullopt;
}

[[noreturn]] void throw_errno(int error, const std::string& what) {
  throw std::system_error(error, std::generic_category(), what);
}

}  // namespace

std::string LockHolder::describe() const {
  return fmt::format("pid {} on host {} since {}: {}", pid, host, since, command);
}

FolderLock::FolderLock(const std::filesystem::path& dir, std::string command) {
  const auto path = dir / kLockFile;
  m_fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (m_fd < 0) throw_errno(errno, "cannot open " + path.string());
  flock lock = whole_file(F_WRLCK);
  if (::fcntl(m_fd, F_OFD_SETLK, &lock) != 0) {
    const int error = errno;
    if (error != EAGAIN && error != EACCES) {
      ::close(m_fd);
      throw_errno(error, "cannot lock " + path.string());
    }
    const auto holder = read_holder_record(m_fd);
    ::close(m_fd);
    throw FolderBusy(fmt::format(
        "{} is in use by another raintrace ({}); run again when it has finished (lock: {})",
        dir.string(), holder ? holder->describe() : std::string{"it has not said who it is yet"},
        path.string()));
  }
  if (command.size() > kMaxCommand) command = command.substr(0, kMaxCommand) + "…";
  m_holder.pid = static_cast<long>(::getpid());
  m_holder.host = host_name();
  m_holder.command = std::move(command);
  m_holder.since = utc_now();
  m_holder.run_id = random_run_id();
  const std::string record = nlohmann::json{{"pid", m_holder.pid},
                                            {"host", m_holder.host},
                                            {"command", m_holder.command},
                                            {"since", m_holder.since},
                                            {"run_id", m_holder.run_id}}
                                 .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) +
                             "\n";
  if (::ftruncate(m_fd, 0) != 0 ||
      ::pwrite(m_fd, record.data(), record.size(), 0) != static_cast<ssize_t>(record.size())) {
    const int error = errno;
    ::close(m_fd);
    throw_errno(error, "cannot write " + path.string());
  }
}

FolderLock::~FolderLock() {
  if (m_fd < 0) return;
  // An empty file says nobody holds the folder; the file itself stays (deleting it would let
  // two processes lock two different files of the same name).
  [[maybe_unused]] const int ignored = ::ftruncate(m_fd, 0);
  ::close(m_fd);  // releases the lock
}

FolderLock::FolderLock(FolderLock&& other) noexcept
    : m_fd{other.m_fd}, m_holder{std::move(other.m_holder)} {
  other.m_fd = -1;
}

std::optional<LockHolder> lock_holder(const std::filesystem::path& dir) {
  const auto path = dir / kLockFile;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  flock probe = whole_file(F_WRLCK);
  const bool can_test = ::fcntl(fd, F_OFD_GETLK, &probe) == 0;
  std::optional<LockHolder> holder;
  if (!can_test || probe.l_type != F_UNLCK) holder = read_holder_record(fd);
  if (holder && holder->run_id.empty()) holder.reset();
  ::close(fd);
  return holder;
}

void require_lock_held_by(const std::filesystem::path& dir, std::string_view run_id) {
  const auto holder = lock_holder(dir);
  if (holder && holder->run_id == run_id) return;
  throw std::runtime_error(fmt::format(
      "{} no longer belongs to the run that submitted this task (run {}): {}", dir.string(), run_id,
      holder ? "it is now used by " + holder->describe() : std::string{"nobody holds it"}));
}

}  // namespace raintrace::output
