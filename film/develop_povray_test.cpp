// With the real POV-Ray (ctest label `povray`; skipped without povray): an OpenEXR frame written
// by `+FE` keeps values above 1, and develops as the contract says.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "film/develop.h"
#include "film/display_transform.h"
#include "film/image_file.h"
#include "tests/support/command.h"

namespace raintrace::film {
namespace {

namespace fs = std::filesystem;

bool have_povray() { return std::system("command -v povray >/dev/null 2>&1") == 0; }

// Four vertical bands, 10 px each, of self-lit patches (emission only, no lights): black
// background, 0.18 (middle grey), 8 (a lamp three and a half stops over white), black.
// assumed_gamma 1.0 as in raintrace's scenes: the EXR holds these values linearly.
constexpr const char* kScene = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -1> look_at <0, 0, 0> right x * 4 up y * 2 }
background { rgb 0 }
#declare Glow = finish { emission 1 diffuse 0 ambient 0 specular 0 }
box { <-1, -1, 0>, <0, 1, 0.1> pigment { rgb 0.18 } finish { Glow } }
box { <0, -1, 0>, <1, 1, 0.1> pigment { rgb 8 } finish { Glow } }
)";

TEST(PovRayHdr, ExrKeepsALampAt8AndDevelopsItByTheContract) {
  if (!have_povray()) GTEST_SKIP() << "povray is not installed: POV-Ray tests skipped";
  const fs::path dir = raintrace::test_support::process_scratch_path("raintrace_film_povray");
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "patches.pov") << kScene;
  const std::string command = "cd '" + dir.string() +
                              "' && povray +Ipatches.pov +Opatches.exr +FE +W40 +H20 -A -D -V "
                              ">povray.log 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << "see " << (dir / "povray.log");

  const RgbImage exr = read_rgb_image(dir / "patches.exr");
  ASSERT_EQ(exr.width, 40);
  ASSERT_EQ(exr.height, 20);
  // Half floats: 8 is exact, 0.18 is within half a unit in the last place (2⁻¹¹ relative).
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(exr.at(5, 10, c), 0.0f);
    EXPECT_NEAR(exr.at(15, 10, c), 0.18f, 0.18f / 2048.0f);
    EXPECT_EQ(exr.at(25, 10, c), 8.0f);
    EXPECT_EQ(exr.at(35, 10, c), 0.0f);
  }

  const DisplayTransform filmic;
  // The curve alone first: no bloom, grain or vignetting.
  DevelopSettings settings{
      .look = Look::medium_contrast, .bloom = 0.0, .grain = 0.0, .vignette = 0.0};
  const RgbImage developed = develop(exr, settings, {}, filmic);
  // Black stays black, grey is half, the lamp is bright but not clipped (3.5 stops below
  // Filmic's white at 16.29): its display value is Filmic's value for 8, about 0.978.
  EXPECT_LT(developed.at(5, 10, 0), 0.5f / 255.0f);
  EXPECT_NEAR(developed.at(15, 10, 0), 0.5, 0.002);
  RgbImage lamp(1, 1, 8.0f);
  EXPECT_EQ(developed.at(25, 10, 1),
            filmic.to_display(lamp, View::filmic, Look::medium_contrast).at(0, 0, 1));
  EXPECT_GT(developed.at(25, 10, 1), 0.95f);
  EXPECT_LT(developed.at(25, 10, 1), 1.0f - 1.0f / 255.0f);

  // One stop less light on the sensor: the lamp now develops as 4 would.
  settings.exposure_ev = -1.0;
  RgbImage four(1, 1, 4.0f);
  EXPECT_EQ(develop(exr, settings, {}, filmic).at(25, 10, 0),
            filmic.to_display(four, View::filmic, Look::medium_contrast).at(0, 0, 0));

  // With bloom the lamp's glow reaches the black band beside it.
  settings = {.exposure_ev = -4.0,
              .look = Look::medium_contrast,
              .bloom = 0.2,
              .grain = 0.0,
              .vignette = 0.0};
  const RgbImage glowing = develop(exr, settings, {}, filmic);
  EXPECT_GT(glowing.at(35, 10, 0), developed.at(35, 10, 0) + 2.0f / 255.0f);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace raintrace::film
