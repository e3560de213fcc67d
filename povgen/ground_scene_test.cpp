// The wet ground's part of the output folder: scene.inc's declarations, files, frame text.
#include "povgen/ground_scene.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "povgen/frame_text.h"
#include "povgen/frame_values.h"
#include "povgen/output_folder.h"
#include "povgen/scene_files.h"
#include "tests/support/command.h"

namespace raintrace::povgen {
namespace {

namespace fs = std::filesystem;

ExportParams with_puddles() {
  ExportParams look;
  look.ground.puddles.coverage = 0.25;
  look.rain.rate_mm_per_h = 5.0;
  return look;
}

TEST(GroundScene, OnlyScenesWithPuddlesIncludeTheGround) {
  ExportParams look;
  EXPECT_FALSE(ground_applies(look));  // "automatic", unresolved: none
  EXPECT_EQ(ground_scene_text(look), "");
  EXPECT_EQ(scene_inc_text(look).find("raintrace_ground.inc"), std::string::npos);
  look = with_puddles();
  EXPECT_TRUE(ground_applies(look));
  const std::string inc = scene_inc_text(look);
  // Before the environment (it calls RT_WetGround), after the camera it describes.
  const auto ground = inc.find("#include \"raintrace_ground.inc\"");
  ASSERT_NE(ground, std::string::npos);
  EXPECT_LT(ground, inc.find("#include \"environment.inc\""));
  EXPECT_LT(inc.find("#declare RT_CameraPosition"), ground);
}

TEST(GroundScene, DeclaresTheCameraTheMasksWereMadeForAndTheRainsRoughness) {
  const std::string text = ground_scene_text(with_puddles());
  EXPECT_NE(text.find("#declare RT_GroundLookAt=<0,1.6,0>;\n"), std::string::npos) << text;
  EXPECT_NE(text.find("#declare RT_GroundAngle=60;\n"), std::string::npos);
  EXPECT_NE(text.find("#declare RT_GroundWidth=640;\n#declare RT_GroundHeight=360;\n"),
            std::string::npos);
  EXPECT_NE(text.find("#declare RT_PuddleMask=\"textures/puddle_mask.png\";\n"), std::string::npos);
  // sim::ripple_slope_rms(5 mm/h, 0.5 s) = 0.01142.
  EXPECT_NE(text.find("#declare RT_RippleRoughness=0.01142"), std::string::npos) << text;
  // Changing the puddles changes scene.inc (the plate's and frames' input hashes cover it).
  ExportParams other = with_puddles();
  other.ground.puddles.seed = 2;
  EXPECT_NE(ground_scene_text(other), text);
}

TEST(GroundScene, FrameDeclaresItsTimeAndNamesItsRippleMapWithItsHash) {
  FrameValues values;
  values.index = 12;
  values.ground = true;
  values.time_s = 0.5;
  EXPECT_NE(frame_text(values).find("#declare RT_Time=0.5;\n#include \"scene.inc\""),
            std::string::npos);
  values.ripples.width = 1;
  values.ripples.height = 1;
  values.ripples.height_m = {0.0f};
  values.ripples.film = {0.0f};
  const std::string flat = frame_text(values);
  EXPECT_NE(flat.find("#declare RT_RippleMap=\"ripples/ripple_0012.png\"; // "), std::string::npos)
      << flat;
  values.ripples.height_m = {0.001f};
  EXPECT_NE(frame_text(values), flat);
}

TEST(GroundScene, SharedFilesHoldTheIncludeAndTheMaskFramesTheirMaps) {
  const fs::path dir = raintrace::test_support::process_scratch_path("raintrace_ground_scene_test");
  fs::remove_all(dir);
  ExportParams look = with_puddles();
  look.width = 64;
  look.height = 36;
  const std::string hash = write_shared_files(dir, look, 1, dir, {1, 1});
  EXPECT_TRUE(fs::is_regular_file(dir / "raintrace_ground.inc"));
  EXPECT_TRUE(fs::is_regular_file(dir / "textures" / "puddle_mask.png"));
  look.ground.puddles.coverage = 0.5;
  EXPECT_NE(write_shared_files(dir, look, 1, dir, {1, 1}), hash);

  FrameValues values;
  values.index = 1;
  values.ground = true;
  values.ripples.width = 64;
  values.ripples.height = 36;
  values.ripples.height_m.assign(64 * 36, 0.0f);
  values.ripples.film.assign(64 * 36, 0.0f);
  write_frame_file(dir / "frames" / "frame_0001.pov", values, hash, 1);
  EXPECT_TRUE(fs::is_regular_file(dir / "ripples" / "ripple_0001.png"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace raintrace::povgen
