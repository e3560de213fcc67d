// The light a lightning channel sends the camera, measured with the real POV-Ray: it is a
// return stroke's per metre of channel whatever radius the channel is drawn with, so
// `[lightning] trunk_radius_m` sets how wide a bolt looks, not how bright it is.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "povgen/frame_text.h"
#include "povgen/frame_values.h"
#include "povgen/output_folder.h"
#include "povgen/povray_test_support.h"
#include "sim/frame.h"

namespace raintrace::povgen {
namespace {

namespace fs = std::filesystem;

/// The light of a straight trunk of `radius` alone under a black sky: Σ of the green channel of
/// a 200×150 render without antialiasing. The trunk stands 105 m ahead, seen through 10°, where
/// a pixel spans 9 cm: a 0.3 m channel is 6.5 pixels wide and its glow (8 radii) 52. It leans 2 m
/// over its 40 m, so that its edges cross the pixel grid at every phase down the picture.
double bolt_light(const std::string& name, float radius) {
  ExportParams look;
  look.width = 200;
  look.height = 150;
  look.camera.fov_deg = 10.0;
  look.camera.look_at = {0.0, 1.6, 100.0};
  look.rain_medium = false;
  const fs::path dir = testing::empty_scratch_folder("bolt_light_test_" + name);
  write_file_atomic(dir / "black_sky.inc", "background { rgb 0 }\n");
  look.environment.include_path = "black_sky.inc";
  write_shared_files(dir, look, 1, dir, {1, 1});

  sim::Frame frame;
  frame.index = 1;
  sim::Bolt bolt;
  bolt.brightness = 1.0f;
  bolt.branch_brightness = 1.0f;
  bolt.segments.push_back({{-1.0f, 21.6f, 100.0f}, {1.0f, -18.4f, 100.0f}, radius, 0});
  frame.bolts.push_back(bolt);
  write_file_atomic(dir / "frames" / "frame_0001.pov", frame_text(build_frame_values(frame, look)));
  EXPECT_EQ(testing::run_povray(
                dir, "frames/frame_0001.pov +W200 +H150 +FE -A +L. +WT1 +Oimages/bolt.exr"),
            0)
      << name << "\n"
      << testing::log_of(dir);
  const std::vector<float> rgb = testing::read_rgb(dir / "images" / "bolt.exr");
  EXPECT_EQ(rgb.size(), 200u * 150u * 3u) << name;
  double sum = 0.0;
  for (std::size_t i = 1; i < rgb.size(); i += 3) sum += rgb[i];
  fs::remove_all(dir);
  return sum;
}

TEST(PovRayBoltLight, AChannelDrawnThinnerSendsTheSameLightPerMetre) {
  SKIP_WITHOUT_POVRAY();
  const double trunk = bolt_light("trunk", kBoltLightTrunkRadius_m);
  const double thinner = bolt_light("thinner", 0.5f * kBoltLightTrunkRadius_m);
  ASSERT_GT(trunk, 0.0);
  // Before, the light went with the radius: the thinner channel sent half of it.
  EXPECT_NEAR(thinner / trunk, 1.0, 0.05) << "trunk " << trunk << ", thinner " << thinner;
}

}  // namespace
}  // namespace raintrace::povgen
