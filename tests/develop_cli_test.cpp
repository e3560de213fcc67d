// The camera end to end, through the `raintrace` program and the real POV-Ray (label povray): a
// frame of three known lights — a lamp at 300, middle grey 0.18 and black — is rendered to EXR
// and developed, and the PNG keeps highlights and blacks where Filmic's contract says
// (docs/hdr-pipeline.md, film/display_transform.h); the EXR keeps the light itself; the PNG is
// its EXR developed, as `raintrace compare` checks.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <vector>

#include "output/manifest.h"
#include "render/povray_command.h"
#include "render/test_folder.h"
#include "tests/cli_test_support.h"

namespace raintrace::render {
namespace {

namespace fs = std::filesystem;
using clitest::run_raintrace;

constexpr int kWidth = 64;
constexpr int kHeight = 36;
// Pixel columns inside each patch (the orthographic camera spans x in [-2, 2] over 64 pixels).
constexpr int kLampColumn = 8;    // x = -1.44, in the lamp [-1.8, -1.0]
constexpr int kGreyColumn = 32;   // x = 0.03, in the grey card [-0.4, 0.4]
constexpr int kBlackColumn = 56;  // x = 1.53: the black background, 40 pixels from the lamp

/// A frame that is its own scene: emission only, no light sources, so each patch's value is
/// its emission exactly.
constexpr const char* kThreeLights = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0,0,-5> look_at <0,0,0> right x*4 up y*2.25 }
background { rgb 0 }
box { <-1.8,-1,0>, <-1.0,1,0.1> pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 300 } }
box { <-0.4,-1,0>, <0.4,1,0.1> pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 0.18 } }
)";

/// The values of row `y` of an image, channel 0 (every patch is grey), as stored (float).
std::vector<float> row(const fs::path& path, int y) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) return {};
  std::vector<float> px(std::size_t(kWidth) * kHeight * 3);
  in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, px.data());
  std::vector<float> out;
  for (int x = 0; x < kWidth; ++x) out.push_back(px[(std::size_t(y) * kWidth + x) * 3]);
  return out;
}

/// Renders the three lights with `raintrace render OUT`, developed as `develop` says.
fs::path render_three_lights(const std::string& name, const output::DevelopSpec& develop) {
  const auto dir = testing::fresh_test_dir(name);
  testing::write_test_folder(dir / "out", {.frames = 1, .width = kWidth, .height = kHeight});
  testing::replace_frame(dir / "out", 1, kThreeLights);
  auto manifest = output::read_manifest(dir / "out/manifest.json");
  manifest.develop = develop;
  output::write_manifest(dir / "out/manifest.json", manifest);
  const auto r = run_raintrace({"render", (dir / "out").string(), "--no-movie"}, dir / "log");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return dir / "out";
}

class PovrayDevelopCli : public testing::PovrayTest {};

TEST_F(PovrayDevelopCli, TheCurveKeepsHighlightsWhiteBlacksBlackAndGreyAtHalf) {
  // Bloom, grain and vignetting off: the Filmic view with its default look alone.
  output::DevelopSpec curve;
  curve.settings.bloom = 0;
  curve.settings.grain = 0;
  curve.settings.vignette = 0;
  const fs::path out = render_three_lights("develop_curve", curve);
  // The EXR holds the light itself: the lamp's 300 survives (half float), black is 0.
  const auto light = row(out / final_image_name(Pass::image, 1), kHeight / 2);
  ASSERT_EQ(light.size(), std::size_t(kWidth));
  EXPECT_EQ(light[kLampColumn], 300.0f);
  EXPECT_NEAR(light[kGreyColumn], 0.18f, 1e-3f);  // half float: 0.18 is stored as 0.17993
  EXPECT_EQ(light[kBlackColumn], 0.0f);
  // The PNG: everything 6.5 stops above grey (16.29) is white, the only clipping; scene black
  // (0.00018 and below) shows below half an 8-bit step; every look keeps grey at 0.5
  // (127.5/255, within the LUT's interpolation).
  const auto shown = row(out / developed_image_name(1), kHeight / 2);
  ASSERT_EQ(shown.size(), std::size_t(kWidth));
  EXPECT_EQ(shown[kLampColumn], 1.0f);
  EXPECT_NEAR(shown[kGreyColumn] * 255.0f, 127.5f, 1.5f);
  EXPECT_EQ(shown[kBlackColumn], 0.0f);
}

TEST_F(PovrayDevelopCli, TheDefaultCameraKeepsTheLampWhiteAndTheFarShadowNearBlack) {
  // Default develop: bloom 0.04 scatters 4 % of the light around the frame (energy-conserving),
  // grain 0.02, vignetting 0.5. The lamp keeps at least (1 − 0.04)·300, far above 16.29: white.
  // At 64 px the glare's widest Gaussian has σ = 9.1 px (film/bloom.h, level 3) and weighs 1/8:
  // 40 px from the lamp's edge (4.4 σ) it brings 0.04 · 1/8 · 300 · 5e-6 ≈ 8e-6, below scene
  // black (0.00018), and grain is none in black: the far shadow stays 0. The grey card, 16 px
  // from the lamp, is lifted by the glare (+9/255 measured); grain on mid-grey is 0.2/255 RMS.
  const fs::path out = render_three_lights("develop_default", output::DevelopSpec{});
  const auto shown = row(out / developed_image_name(1), kHeight / 2);
  ASSERT_EQ(shown.size(), std::size_t(kWidth));
  EXPECT_EQ(shown[kLampColumn], 1.0f);
  EXPECT_EQ(shown[kBlackColumn], 0.0f);
  EXPECT_GT(shown[kGreyColumn] * 255.0f, 127.0f);  // glare only ever adds light here
  EXPECT_LT(shown[kGreyColumn] * 255.0f, 127.5f + 16.0f);
  // The PNG is its EXR developed, as the PNG's description says: `raintrace compare` finds them
  // equal within half an 8-bit step (rounding).
  const auto check =
      run_raintrace({"compare", (out / developed_image_name(1)).string(),
                     (out / final_image_name(Pass::image, 1)).string(), "--fail", "0.002"},
                    out.parent_path() / "compare.log");
  EXPECT_EQ(check.exit_code, 0) << check.output;
  EXPECT_NE(check.output.find("HDR input developed for comparison: raintrace develop: "
                              "exposure_ev=0 view=filmic look=medium-high-contrast bloom=0.04 "
                              "grain=0.02 vignette=0.5 fov_deg=60 seed=0 frame=1"),
            std::string::npos)
      << check.output;
}

}  // namespace
}  // namespace raintrace::render
