// Helpers for tests that run the `raintrace` program as a user would: run it with its output in
// a log, write a small rain scene, and compare a folder with a clean render of the same scene.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "render/process.h"

namespace raintrace::clitest {

std::string read_all(const std::filesystem::path& path);

struct Run {
  int exit_code = 0;
  std::string output;  ///< stdout and stderr together, as a log file (not a terminal) gets them
};

/// The raintrace program (RAINTRACE_BINARY) with `args`, its output going to `log`.
render::ProcessSpec raintrace_spec(const std::vector<std::string>& args,
                                   const std::filesystem::path& log);
/// Runs it to the end, with `env` set (or replaced) in its environment.
Run run_raintrace(const std::vector<std::string>& args, const std::filesystem::path& log,
                  const std::map<std::string, std::string>& env = {});

/// A small rain scene (about 1 000 drops in view at 64x36, night_street, preview) of `frames`
/// frames, written to dir/name; `extra` is appended (more TOML).
std::filesystem::path write_scene(const std::filesystem::path& dir, int frames,
                                  const std::string& name = "small.toml", int seed = 7,
                                  const std::string& extra = "");

/// The folder holds what a clean render of the same scene (in `clean`) holds: the same frame
/// files byte for byte, the same images and masks pixel for pixel (decoded: PNG bytes carry a
/// timestamp), no image or frame file the clean one lacks, and a manifest listing the same
/// frames with the same input hashes, every one rendered. The contact sheet, when the clean one
/// has one, matches pixel for pixel too.
void expect_same_as_clean_render(const std::filesystem::path& folder,
                                 const std::filesystem::path& clean);

}  // namespace raintrace::clitest
