// Test helper: writes a tiny hand-made output folder in the exporter's layout (scene.ini,
// scene.pov dispatcher, frames/frame_NNNN.pov, manifest.json), so render/ can be tested without
// the simulator or the exporter.
#pragma once

#include <gtest/gtest.h>
#include <filesystem>
#include <map>
#include <string>

#include "render/progress.h"

namespace raintrace::render::testing {

struct TestFolderSpec {
  int frames = 6;
  int width = 64;
  int height = 36;
  int spheres = 200;  ///< per frame; more makes each frame slower to parse and trace
  /// Write mask.ini, mask.pov and frames/mask_NNNN.pov, and list masks in the manifest, as the
  /// exporter does for a scene exported with masks.
  bool masks = false;
  /// Also write plate.ini, plate.pov and environment.inc as the preview exporter does: scene.inc
  /// then draws textures/environment_plate.exr when it is there at width×height, and otherwise
  /// includes environment.inc. Each frame says which in its log (#debug): "raintrace:
  /// environment plate used" or "raintrace: full environment".
  bool plate = false;
};

/// Creates (replacing) dir with the folder; each frame is a different, deterministic scene.
void write_test_folder(const std::filesystem::path& dir, const TestFolderSpec& spec = {});

/// Rewrites one frame's .pov with `text` and updates its input_hash in manifest.json (as an
/// export whose frame changed would).
void replace_frame(const std::filesystem::path& dir, int frame, const std::string& text);

/// A frame that takes POV-Ray some 7 s to trace on two cores at 320×180 (ten 32×32 blocks
/// across): an isosurface sought to a hundred-thousandth, its surface lumpy with granite. For
/// replace_frame, where a test needs a frame still tracing after a few seconds.
inline constexpr const char* kSlowFrame =
    "#include \"scene.inc\"\n"
    "#declare Grain = function { pattern { granite scale 0.3 } }\n"
    "isosurface { function { x * x + y * y + z * z - 4 + 0.5 * Grain(x, y, z) }\n"
    "             contained_by { box { -2.5, 2.5 } } max_gradient 300 accuracy 0.00001\n"
    "             pigment { rgb 1 } }\n";

/// A render's progress callback (std::ref it into on_progress) that keeps the first ETA and
/// how many pictures were finished when it came.
struct FirstEta {
  double seconds = -1.0;
  int finished_then = -1;
  void operator()(const RenderProgress& p) {
    if (seconds < 0.0 && p.eta_seconds >= 0.0) {
      seconds = p.eta_seconds;
      finished_then = p.done + p.failed;
    }
  }
};

/// True when `povray` is in PATH.
bool system_has_povray();

/// Tests that run the real POV-Ray: skipped, with the install command, where it is missing.
class PovrayTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!system_has_povray()) GTEST_SKIP() << "POV-Ray not installed (apt-get install povray)";
  }
};

/// A folder dir/fake_bin holding a `povray` that, asked to render `ini` (its first argument),
/// fails `failures` times the way POV-Ray 3.7 does when its worker thread misses its 3 s start-up
/// deadline on a loaded machine (kPovrayStartupTimeout, exit code 1, no image), then hands over
/// to the real POV-Ray. It counts the renders of `ini` it was asked for in dir/starts.
std::filesystem::path povray_that_does_not_start(const std::filesystem::path& dir,
                                                 const std::string& ini, int failures);

/// PATH with `bin` ahead of the rest of it, as an environment for a child process.
std::map<std::string, std::string> path_with(const std::filesystem::path& bin);

/// A fresh empty folder under the system temp dir, named after the running test.
std::filesystem::path fresh_test_dir(const std::string& name);

}  // namespace raintrace::render::testing
