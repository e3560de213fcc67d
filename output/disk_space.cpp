// statvfs on the output folder.
#include "output/disk_space.h"

#include <sys/statvfs.h>
#include <unistd.h>
#include <cerrno>
#include <system_error>

namespace raintrace::output {

bool out_of_space(const std::filesystem::path& dir, std::uint64_t needed) {
  struct statvfs fs {};
  if (::statvfs(dir.c_str(), &fs) != 0) return false;
  const auto blocks = ::geteuid() == 0 ? fs.f_bfree : fs.f_bavail;
  return static_cast<std::uint64_t>(blocks) * fs.f_frsize < needed;
}

void throw_if_out_of_space(const std::filesystem::path& dir, std::uint64_t needed,
                           const std::string& what) {
  if (out_of_space(dir, needed)) throw std::system_error(ENOSPC, std::generic_category(), what);
}

}  // namespace raintrace::output
