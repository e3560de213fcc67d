// Scene → export input, and the command line from /proc.
#include "cli/folder_run.h"

#include <fcntl.h>
#include <fmt/core.h>
#include <unistd.h>
#include <CLI/CLI.hpp>
#include <algorithm>
#include <stdexcept>
#include <vector>

#include "cli/options.h"
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

output::FolderState claim_folder(const std::filesystem::path& out, const Scene& scene,
                                 const output::SceneToExport& to_export, bool force,
                                 output::ClaimNote* note) {
  auto folder =
      output::FolderState::claim(out, output::identity_of(canonical_scene_text(scene), to_export),
                                 force, this_command(), note);
  folder.set_develop({scene.develop, scene.look.camera.fov_deg, scene.look.aperture_m});
  return folder;
}

std::string hand_edit_note(const output::FolderState& folder, bool exporting) {
  const auto edited = exporting ? folder.hand_edited_inputs() : folder.newly_edited_inputs();
  if (edited.empty()) return "";
  constexpr std::size_t kNamed = 3;
  std::string files;
  for (std::size_t i = 0; i < std::min(edited.size(), kNamed); ++i) {
    files += (i == 0 ? "" : ", ") + edited[i];
  }
  if (edited.size() > kNamed) files += fmt::format(" and {} more", edited.size() - kNamed);
  const bool one = edited.size() == 1;
  if (exporting) {
    return fmt::format(
        "{} in {} {} edited by hand: this export writes the scene's own files over the edits "
        "(to render the edits instead, render the folder: raintrace render {})",
        files, folder.dir().string(), one ? "was" : "were", folder.dir().string());
  }
  return fmt::format(
      "{} edited in {} since raintrace saw {}: the frames that read {} are "
      "rendered again",
      files, folder.dir().string(), one ? "it" : "them", one ? "it" : "them");
}

void add_limit_options(CLI::App& command, LimitArgs& limits) {
  command.add_option("--max-memory", limits.max_memory,
                     "Most memory the run may need, e.g. 8G (default: 4G, or half of this "
                     "machine's memory if less); the run stops before it starts past it");
  command
      .add_option("--max-drop-steps", limits.max_drop_steps,
                  "Most simulation work, drops x substeps, e.g. 1e13 (default 1e12, about "
                  "3 hours)")
      ->check(positive_number());
}

void check_run_budget(const output::SceneToExport& scene, output::FrameSpan range,
                      int povray_processes, const LimitArgs& limits) {
  output::BudgetLimits l;
  if (limits.max_drop_steps > 0) l.max_drop_steps = limits.max_drop_steps;
  if (!limits.max_memory.empty()) {
    const auto bytes = output::parse_byte_size(limits.max_memory);
    if (!bytes) {
      throw std::invalid_argument(
          fmt::format("--max-memory takes a size such as 8G or 512M, not '{}'",
                      limits.max_memory.substr(0, 40)));
    }
    l.max_memory_bytes = *bytes;
  }
  output::check_budget(output::estimate_budget(scene, range, povray_processes), l);
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
