// Every example in examples/ exported (frame 1), rendered by the real POV-Ray at 64×36 and
// developed as `raintrace render` develops it (the scene's [camera] develop keys): the picture
// is not blank, and it differs from the same scene without rain (rain.rate 0), so the rain
// really reaches the picture. Label `povray`; skipped when povray is missing.
// To stay within the test budget the simulation skips its prewarm (World fills the volume at
// steady-state density before it, so frame 1 is already full of rain) and uses 10 ms substeps.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/folder_run.h"
#include "cli/scene.h"
#include "film/develop.h"
#include "output/budget.h"
#include "output/export.h"
#include "output/folder_state.h"
#include "tests/support/command.h"
#include "tests/support/pixels.h"

namespace raintrace {
namespace {

namespace fs = std::filesystem;

bool have_povray() { return std::system("command -v povray >/dev/null 2>&1") == 0; }

std::vector<fs::path> examples() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(fs::path{RAINTRACE_SOURCE_DIR} / "examples")) {
    if (entry.path().extension() == ".toml") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

using raintrace::test_support::read_rgb;

/// Exports frame 1 of the scene at 64×36 into dir, renders it (with extra POV-Ray options) and
/// develops it; returns the developed pixels.
std::vector<float> export_and_render(cli::Scene scene, const fs::path& dir,
                                     const std::string& options = "") {
  scene.look.width = 64;
  scene.look.height = 36;
  scene.look.quality = povgen::Quality::preview;
  scene.look.camera.aspect = scene.sim.camera.aspect = 64.0 / 36.0;
  scene.sim.prewarm_s = 0.0;
  scene.sim.substep_s = 0.01;
  fs::remove_all(dir);
  {
    const output::SceneToExport e = cli::scene_to_export(scene);
    auto folder = cli::claim_folder(dir, scene, e, false, nullptr);
    output::export_frames(folder, e, {1, 1});
  }
  const std::string command = "cd '" + dir.string() + "' && povray scene.ini +SF1 +EF1 -D -V " +
                              options + " >povray.log 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << "povray failed in " << dir;
  static const film::DisplayTransform display;
  film::develop_file(dir / "images" / "frame_0001.exr", dir / "images" / "frame_0001.png",
                     scene.develop,
                     {.fov_deg = scene.look.camera.fov_deg,
                      .seed = scene.sim.seed,
                      .frame = 1,
                      .aperture_m = scene.look.aperture_m},
                     display);
  return read_rgb(dir / "images" / "frame_0001.png");
}

/// The images (scene-linear EXRs) povray scene.ini renders in `dir`, by file name.
std::vector<std::string> render_scene_ini(const fs::path& dir) {
  fs::remove_all(dir / "images");
  fs::create_directories(dir / "images");
  const std::string command =
      "cd '" + dir.string() + "' && povray scene.ini -D -V >povray.log 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << "povray scene.ini failed in " << dir;
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir / "images")) {
    if (entry.is_regular_file()) names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

/// Exports frames first..last of the scene into dir, as `raintrace export --frames` does.
void export_range(const cli::Scene& scene, const fs::path& dir, int first, int last) {
  const output::SceneToExport e = cli::scene_to_export(scene);
  auto folder = output::FolderState::claim(dir, output::identity_of(scene.text, e), false, "test");
  output::export_frames(folder, e, {first, last});
}

TEST(PartialExport, SceneIniRendersExactlyTheExportedFrames) {
  if (!have_povray()) GTEST_SKIP() << "povray is not installed";
  cli::Scene scene = cli::load_scene_file(fs::path{RAINTRACE_SOURCE_DIR} / "examples/default.toml");
  scene.look.width = 32;
  scene.look.height = 18;
  scene.sim.prewarm_s = 0.0;
  scene.sim.substep_s = 0.01;
  const fs::path dir = raintrace::test_support::process_scratch_path("raintrace_partial_export");
  fs::remove_all(dir);
  // Once `povray scene.ini` of a folder exported with --frames 1-2 failed at frame 3.
  export_range(scene, dir, 2, 3);
  EXPECT_EQ(render_scene_ini(dir), (std::vector<std::string>{"frame_0002.exr", "frame_0003.exr"}));
  // A later export that joins the earlier frames renders them all…
  export_range(scene, dir, 4, 4);
  EXPECT_EQ(render_scene_ini(dir),
            (std::vector<std::string>{"frame_0002.exr", "frame_0003.exr", "frame_0004.exr"}));
  // …and one that leaves a gap renders its own frames only.
  export_range(scene, dir, 7, 7);
  EXPECT_EQ(render_scene_ini(dir), (std::vector<std::string>{"frame_0007.exr"}));
  fs::remove_all(dir);
}

class ExampleRender : public ::testing::TestWithParam<fs::path> {};

TEST_P(ExampleRender, FitsTheDefaultMemoryAndWorkLimitsWithRoomToSpare) {
  // The limits (output/budget.h) stop runaway scenes; no example may come near them, rendered
  // whole with the default 4 POV-Ray processes: a quarter of the 4 GiB default memory limit
  // (of a machine with 8 GiB or more; the test must not depend on the machine it runs on).
  const cli::Scene scene = cli::load_scene_file(GetParam());
  const auto e = cli::scene_to_export(scene);
  const output::Budget b = output::estimate_budget(e, {1, scene.frames}, 4);
  EXPECT_LT(b.total_bytes(), 4.0 * 1024 * 1024 * 1024 / 4) << GetParam();
  EXPECT_LT(b.drop_steps, output::BudgetLimits{}.max_drop_steps / 100) << GetParam();
}

TEST_P(ExampleRender, RendersRainThatChangesThePicture) {
  if (!have_povray()) GTEST_SKIP() << "povray is not installed: example renders skipped";
  const cli::Scene scene = cli::load_scene_file(GetParam());
  const fs::path work = raintrace::test_support::checkout_scratch_folder(
                            "raintrace_examples_render_test", RAINTRACE_SOURCE_DIR) /
                        GetParam().stem();
  const auto rain = export_and_render(scene, work / "rain");
  ASSERT_FALSE(rain.empty());
  const auto [lo, hi] = std::minmax_element(rain.begin(), rain.end());
  EXPECT_GT(*hi - *lo, 0.05) << "blank image";

  // Dry: no falling rain, and none of the drops closeup.inc beads on the car roof (RT_HeroDrops;
  // other environments ignore it). The closeup's falling rain, 1.5–4 m behind a macro lens
  // focused at 3 cm, is blurred over discs ~300 times its width and changes no pixel: its rain
  // is the drops at the focus.
  cli::Scene dry = scene;
  dry.sim.rain.rate_mm_per_h = 0.0;
  const auto no_rain = export_and_render(dry, work / "dry", "Declare=RT_HeroDrops=0");
  ASSERT_EQ(no_rain.size(), rain.size());
  double difference = 0.0;
  float largest = 0.0f;
  for (std::size_t i = 0; i < rain.size(); ++i) {
    difference += std::fabs(rain[i] - no_rain[i]);
    largest = std::max(largest, std::fabs(rain[i] - no_rain[i]));
  }
  difference /= static_cast<double>(rain.size());
  // Rain must change the picture: some pixel by at least 1/255, and the mean by more than 1e-5
  // of full scale. Rain is faint by physics: a streak covers a pixel only for the share of the
  // exposure its drop spends on it (docs/rain-appearance.md), and at 64×36 a pixel 3 m away is
  // 5 cm wide, so even near drops move a pixel by a few 1/255.
  EXPECT_GE(largest, 1.0f / 255.0f) << "rain does not change any pixel";
  EXPECT_GT(difference, 1e-5) << "rain does not change the picture";
  fs::remove_all(work);
}

INSTANTIATE_TEST_SUITE_P(Examples, ExampleRender, ::testing::ValuesIn(examples()),
                         [](const ::testing::TestParamInfo<fs::path>& example) {
                           return example.param.stem().string();
                         });

}  // namespace
}  // namespace raintrace
