// The environment plate on its own: when it is needed, what it hashes, and how it ends when
// stopped. Renders through render_local are in local_render_test.cpp.
#include "render/environment_plate.h"

#include <gtest/gtest.h>
#include <atomic>
#include <fstream>

#include "output/image_check.h"
#include "render/povray_command.h"
#include "render/process.h"
#include "render/test_folder.h"

namespace raintrace::render {
namespace {

using output::image_is_complete;

void append(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out{path, std::ios::binary | std::ios::app};
  out << text;
}

TEST(EnvironmentPlate, WithoutPlateIniThereIsNothingToDo) {
  const auto dir = testing::fresh_test_dir("plate_none");
  testing::write_test_folder(dir, {.frames = 1});
  EnvironmentPlate plate{dir, 64, 36};
  EXPECT_TRUE(plate.poll());
  EXPECT_FALSE(plate.started());
  EXPECT_TRUE(plate.problem().empty());
  EXPECT_FALSE(std::filesystem::exists(dir / "textures"));
  EXPECT_FALSE(std::filesystem::exists(dir / kPlateLog));
}

TEST(EnvironmentPlate, InputsHashFollowsEachPlateInputButNotTheFrames) {
  const auto dir = testing::fresh_test_dir("plate_hash");
  testing::write_test_folder(dir, {.frames = 2, .plate = true});
  const auto original = environment_plate_inputs_hash(dir);
  testing::replace_frame(dir, 1, "#include \"scene.inc\"\n");
  EXPECT_EQ(environment_plate_inputs_hash(dir), original);
  std::string previous = original;
  for (const char* name : {"plate.ini", "plate.pov", "scene.inc", "environment.inc"}) {
    append(dir / name, "// changed\n");
    const auto now = environment_plate_inputs_hash(dir);
    EXPECT_NE(now, previous) << name;
    previous = now;
  }
  // A materials include appearing (even empty) is a change too.
  append(dir / "raintrace_materials.inc", "");
  EXPECT_NE(environment_plate_inputs_hash(dir), previous);
  previous = environment_plate_inputs_hash(dir);
  // So are the wet ground's include and its puddle mask, which the plate draws.
  append(dir / "raintrace_ground.inc", "");
  EXPECT_NE(environment_plate_inputs_hash(dir), previous);
  previous = environment_plate_inputs_hash(dir);
  std::filesystem::create_directories(dir / "textures");
  append(dir / "textures" / "puddle_mask.png", "x");
  EXPECT_NE(environment_plate_inputs_hash(dir), previous);
}

class PovrayEnvironmentPlate : public testing::PovrayTest {};

TEST_F(PovrayEnvironmentPlate, RendersThePlateAndItsSidecarThenTrustsThem) {
  const auto dir = testing::fresh_test_dir("plate_direct");
  testing::write_test_folder(dir, {.frames = 1, .plate = true});
  {
    EnvironmentPlate plate{dir, 64, 36};
    EXPECT_TRUE(plate.started());
    plate.wait();
    EXPECT_TRUE(plate.problem().empty()) << plate.problem();
  }
  EXPECT_TRUE(image_is_complete(dir / kPlateImage, 64, 36));
  EXPECT_FALSE(std::filesystem::exists(dir / environment_plate_temp_name()));
  EnvironmentPlate again{dir, 64, 36};
  EXPECT_FALSE(again.started());
  // Another frame size makes the plate useless to the frames: it is rendered again.
  EnvironmentPlate other_size{dir, 32, 18};
  EXPECT_TRUE(other_size.started());
}

TEST_F(PovrayEnvironmentPlate, AStalePlateIsGoneBeforePovrayStarts) {
  const auto dir = testing::fresh_test_dir("plate_stale");
  testing::write_test_folder(dir, {.frames = 1, .plate = true});
  EnvironmentPlate{dir, 64, 36}.wait();
  ASSERT_TRUE(std::filesystem::exists(dir / kPlateImage));
  append(dir / "environment.inc", "sphere { <0,3,0>, 1 pigment { rgb <1,0,0> } }\n");
  EnvironmentPlate plate{dir, 64, 36};
  EXPECT_TRUE(plate.started());
  // A frame starting now would find no plate rather than the old one.
  EXPECT_FALSE(std::filesystem::exists(dir / kPlateImage));
  EXPECT_FALSE(std::filesystem::exists(dir / kPlateSidecar));
  plate.wait();
  EXPECT_TRUE(image_is_complete(dir / kPlateImage, 64, 36));
}

TEST_F(PovrayEnvironmentPlate, StopEndsPovrayAndLeavesNoPlate) {
  const auto dir = testing::fresh_test_dir("plate_stop");
  testing::write_test_folder(dir, {.frames = 1, .plate = true});
  std::atomic<bool> stop{true};
  EnvironmentPlate plate{dir, 64, 36, &stop};
  plate.wait();
  EXPECT_TRUE(plate.interrupted());
  EXPECT_EQ(plate.problem(), "interrupted");
  EXPECT_FALSE(std::filesystem::exists(dir / kPlateImage));
  EXPECT_FALSE(std::filesystem::exists(dir / kPlateSidecar));
}

}  // namespace
}  // namespace raintrace::render
