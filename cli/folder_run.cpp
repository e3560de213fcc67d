// Scene → export input, and the command line from /proc.
#include "cli/folder_run.h"

#include <fcntl.h>
#include <unistd.h>
#include <vector>

#include "render/process.h"

namespace raintrace::cli {

output::SceneToExport scene_to_export(const Scene& scene) {
  output::SceneToExport e;
  e.sim = scene.sim;
  e.look = scene.look;
  e.frames = scene.frames;
  e.scene_dir = scene.base_dir.empty() ? scene.source.parent_path() : scene.base_dir;
  return e;
}

std::string this_command() {
  std::string raw;
  const int fd = ::open("/proc/self/cmdline", O_RDONLY | O_CLOEXEC);
  if (fd >= 0) {
    char buffer[4096];
    ssize_t n = 0;
    while (raw.size() < (1U << 20) && (n = ::read(fd, buffer, sizeof buffer)) > 0) {
      raw.append(buffer, static_cast<std::size_t>(n));
    }
    ::close(fd);
  }
  std::vector<std::string> argv;
  std::string arg;
  for (const char c : raw) {
    if (c == '\0') {
      argv.push_back(arg);
      arg.clear();
    } else {
      arg += c;
    }
  }
  if (argv.empty()) return "raintrace";
  argv[0] = "raintrace";  // the name users type, not the build path
  return render::shell_quote_command(argv);
}

}  // namespace raintrace::cli
