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

std::vector<float> read_rgb(const fs::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) return {};
  const OIIO::ImageSpec& spec = in->spec();
  std::vector<float> px(static_cast<std::size_t>(spec.width) * spec.height * 3);
  in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, px.data());
  return px;
}

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
                     scene.develop, {scene.look.camera.fov_deg, scene.sim.seed, 1}, display);
  return read_rgb(dir / "images" / "frame_0001.png");
}

class ExampleRender : public ::testing::TestWithParam<fs::path> {};

TEST_P(ExampleRender, FitsTheDefaultMemoryAndWorkLimitsWithRoomToSpare) {
  // The limits (output/budget.h) stop runaway scenes; no example may come near them, rendered
  // whole with the default 4 POV-Ray processes.
  const cli::Scene scene = cli::load_scene_file(GetParam());
  const auto e = cli::scene_to_export(scene);
  const output::Budget b = output::estimate_budget(e, {1, scene.frames}, 4);
  EXPECT_LT(b.total_bytes(), output::default_max_memory_bytes() / 4) << GetParam();
  EXPECT_LT(b.drop_steps, output::BudgetLimits{}.max_drop_steps / 100) << GetParam();
}

TEST_P(ExampleRender, RendersRainThatChangesThePicture) {
  if (!have_povray()) GTEST_SKIP() << "povray is not installed: example renders skipped";
  const cli::Scene scene = cli::load_scene_file(GetParam());
  const fs::path work =
      fs::temp_directory_path() / "raintrace_examples_render_test" / GetParam().stem();
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
                         [](const ::testing::TestParamInfo<fs::path>& test) {
                           return test.param.stem().string();
                         });

}  // namespace
}  // namespace raintrace
