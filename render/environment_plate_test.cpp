// The environment plate on its own: when it is needed, what it hashes, and how it ends when
// stopped. Renders through render_local are in local_render_test.cpp.
#include "render/environment_plate.h"

#include <fmt/core.h>
#include <gtest/gtest.h>
#include <atomic>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>

#include "output/image_check.h"
#include "render/povray_command.h"
#include "render/process.h"
#include "render/test_folder.h"
#include "render/text_file.h"

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

/// PATH for this process while in scope: the plate's POV-Ray inherits it.
class ScopedPath {
 public:
  explicit ScopedPath(const std::map<std::string, std::string>& env)
      : m_old{std::getenv("PATH") != nullptr ? std::getenv("PATH") : ""} {
    ::setenv("PATH", env.at("PATH").c_str(), 1);
  }
  ~ScopedPath() { ::setenv("PATH", m_old.c_str(), 1); }
  ScopedPath(const ScopedPath&) = delete;
  ScopedPath& operator=(const ScopedPath&) = delete;

 private:
  std::string m_old;
};

// On a loaded machine POV-Ray can give up before it reads plate.ini. Without a plate every
// frame traces the whole environment, so it is started again, as the frames are.
TEST_F(PovrayEnvironmentPlate, APovrayThatDidNotStartIsStartedAgain) {
  const auto dir = testing::fresh_test_dir("plate_not_started");
  testing::write_test_folder(dir / "out", {.frames = 1, .plate = true});
  const ScopedPath path{testing::path_with(
      testing::povray_that_does_not_start(dir, povgen::kPlateIni, kPovrayStartAttempts - 1))};
  EnvironmentPlate plate{dir / "out", 64, 36};
  plate.wait();
  EXPECT_TRUE(plate.problem().empty()) << plate.problem();
  EXPECT_TRUE(image_is_complete(dir / "out" / kPlateImage, 64, 36));
  // Three starts that gave up, then the one that rendered the plate.
  EXPECT_EQ(read_text(dir / "starts"), std::to_string(kPovrayStartAttempts) + "\n");
}

TEST_F(PovrayEnvironmentPlate, APovrayThatNeverStartsLeavesNoPlateAndSaysWhy) {
  const auto dir = testing::fresh_test_dir("plate_never_started");
  testing::write_test_folder(dir / "out", {.frames = 1, .plate = true});
  const ScopedPath path{
      testing::path_with(testing::povray_that_does_not_start(dir, povgen::kPlateIni, 1000))};
  EnvironmentPlate plate{dir / "out", 64, 36};
  plate.wait();
  EXPECT_NE(plate.problem().find(fmt::format("POV-Ray did not start, {} times: {}",
                                             kPovrayStartAttempts, kPovrayStartupTimeout)),
            std::string::npos)
      << plate.problem();
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / kPlateImage));
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / kPlateSidecar));
  EXPECT_EQ(read_text(dir / "starts"), std::to_string(kPovrayStartAttempts) + "\n");
}

}  // namespace
}  // namespace raintrace::render
