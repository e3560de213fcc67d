// One run at a time in an output folder. A run that exports or renders holds an OS lock on
// OUT/raintrace.lock for its whole life; the kernel releases it when the process ends, however
// it ends (kill -9 included), so a lock is never left behind. While held, the file names the
// holder (pid, host, command, since when), so a second run can say who is in the way.
//
// The lock is an open-file-description lock (fcntl F_OFD_SETLK, Linux): unlike a classic POSIX
// lock, closing some other descriptor of the file never drops it, and unlike flock() another
// process can test for it without taking it (F_OFD_GETLK). Slurm array tasks work under the
// submitting run's lock without taking it: they check that it is still held by the run that
// submitted them (require_lock_held_by, with the run id written into their plan).
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace raintrace::output {

struct LockHolder {
  long pid = 0;
  std::string host;
  std::string command;  ///< the holder's command line, cut to a few hundred characters
  std::string since;    ///< UTC, "2026-11-23T18:40:02Z"
  std::string run_id;   ///< 16 random hex digits naming this run
  /// "pid 4242 on host node1 since 2026-11-23T18:40:02Z: raintrace render a.toml -o out"
  [[nodiscard]] std::string describe() const;
};

/// A second run found the folder in use. what() names the folder and the holder.
class FolderBusy : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class FolderLock {
 public:
  /// Creates dir/raintrace.lock if missing and takes its lock without waiting. `command` is
  /// recorded for whoever finds the folder busy. Throws FolderBusy when another process holds
  /// the lock, std::system_error when the file cannot be created, locked or written.
  FolderLock(const std::filesystem::path& dir, std::string command);
  /// Empties the file (nobody holds it) and releases the lock.
  ~FolderLock();
  FolderLock(FolderLock&& other) noexcept;
  FolderLock& operator=(FolderLock&&) = delete;
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

  [[nodiscard]] const LockHolder& holder() const { return m_holder; }

 private:
  int m_fd = -1;
  LockHolder m_holder;
};

/// Who holds dir's lock now; nullopt when nobody does (or there is no lock file). When the
/// filesystem cannot tell (no F_OFD_GETLK), whoever the file names is taken as the holder.
std::optional<LockHolder> lock_holder(const std::filesystem::path& dir);

/// For a process working under another's lock (a Slurm array task): returns when dir's lock is
/// held by the run `run_id`; otherwise throws std::runtime_error saying whose it is instead, so
/// a task left over from a killed run never writes into a folder another run now uses.
void require_lock_held_by(const std::filesystem::path& dir, std::string_view run_id);

}  // namespace raintrace::output
