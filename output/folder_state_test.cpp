// The folder's state owner: whose folder it is, the transitions, and the one up-to-date rule
// with images checked by size and content hash. No POV-Ray: "images" here are files whose
// bytes the tests choose (render/ and tests/ render real ones).
#include "output/folder_state.h"

#include <gtest/gtest.h>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include "output/test_dir.h"
#include "povgen/ground_scene.h"

namespace raintrace::output {
namespace {

namespace fs = std::filesystem;

FolderIdentity identity(const std::string& scene = "scene-a", std::uint64_t seed = 1) {
  FolderIdentity id;
  id.scene_hash = scene;
  id.seed = seed;
  id.width = 64;
  id.height = 36;
  id.fps = 24;
  return id;
}

void write(const fs::path& path, const std::string& bytes) {
  fs::create_directories(path.parent_path());
  std::ofstream{path, std::ios::binary} << bytes;
}

std::string read(const fs::path& path) {
  std::ifstream in{path, std::ios::binary};
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// An export of `frames` frames as export_frames does it, with each frame's file written and
// its "image" rendered (any bytes do: the state checks bytes, not pixels).
void export_and_render(FolderState& folder, int frames, const std::string& shared = "shared") {
  folder.begin_export(shared, {1, frames}, frames);
  for (int n = 1; n <= frames; ++n) {
    write(folder.dir() / frame_scene_name(Pass::image, n), "frame " + std::to_string(n));
    folder.frame_exported(n, shared + "+" + std::to_string(n));
  }
  folder.save();
  for (int n = 1; n <= frames; ++n) {
    write(folder.dir() / final_image_name(Pass::image, n),
          "image bytes of frame " + std::to_string(n));
    folder.rendered(Pass::image, n, 0.5);
  }
}

// Develops every frame as render/ does: the PNG at its final name, then the transition.
void develop_all(FolderState& folder, int frames, const std::string& hash = "develop-a") {
  folder.set_develop_hash(hash);
  for (int n = 1; n <= frames; ++n) {
    write(folder.dir() / developed_image_name(n), "png bytes of frame " + std::to_string(n));
    folder.developed(n, 0.1);
  }
}

TEST(FolderClaim, ANewFolderIsCreatedAndMarkedAsRaintracesAtOnce) {
  const auto dir = testing::fresh_test_dir("claim_new") / "a" / "b";
  {
    const auto folder = FolderState::claim(dir, identity(), false, "test");
    EXPECT_TRUE(fs::exists(dir / kManifest));
    EXPECT_EQ(folder.manifest().identity, identity());
  }
  // Claimed again with the same identity: resumed, nothing said.
  ClaimNote note;
  FolderState::claim(dir, identity(), false, "test", &note);
  EXPECT_TRUE(note.text.empty());
}

TEST(FolderClaim, AFolderInUseIsRefusedAtOnce) {
  const auto dir = testing::fresh_test_dir("claim_busy");
  const auto first = FolderState::claim(dir, identity(), false, "raintrace render a.toml");
  try {
    FolderState::claim(dir, identity(), false, "raintrace render b.toml");
    FAIL() << "two claims";
  } catch (const FolderBusy& e) {
    EXPECT_NE(std::string{e.what()}.find("raintrace render a.toml"), std::string::npos);
  }
  EXPECT_THROW(FolderState::open(dir, "raintrace render dir"), FolderBusy);
}

TEST(FolderClaim, ANonEmptyFolderRaintraceDidNotMakeIsRefusedUnlessForced) {
  const auto dir = testing::fresh_test_dir("claim_foreign");
  write(dir / "notes.txt", "mine");
  write(dir / "images" / "frame_0001.png", "my own picture");
  try {
    FolderState::claim(dir, identity(), false, "test");
    FAIL() << "a foreign folder was claimed";
  } catch (const FolderRefused& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("raintrace did not make it"), std::string::npos) << what;
    EXPECT_NE(what.find("--force"), std::string::npos) << what;
  }
  EXPECT_FALSE(fs::exists(dir / kManifest));
  ClaimNote note;
  { FolderState::claim(dir, identity(), true, "test", &note); }
  EXPECT_NE(note.text.find("raintrace did not make"), std::string::npos) << note.text;
  EXPECT_EQ(read(dir / "notes.txt"), "mine");  // forcing overwrites, it never cleans up
  EXPECT_TRUE(fs::exists(dir / kManifest));
}

TEST(FolderClaim, AnotherToolsManifestIsNotOurs) {
  const auto dir = testing::fresh_test_dir("claim_other_manifest");
  write(dir / kManifest, R"({"name": "web-app"})");
  EXPECT_THROW(FolderState::claim(dir, identity(), false, "test"), FolderRefused);
  EXPECT_THROW(FolderState::open(dir, "test"), FolderRefused);
  EXPECT_EQ(read(dir / kManifest), R"({"name": "web-app"})");
}

TEST(FolderClaim, AnotherSceneIsRefusedAndForceRemovesOnlyWhatTheManifestRecords) {
  const auto dir = testing::fresh_test_dir("claim_other");
  {
    auto folder = FolderState::claim(dir, identity("scene-a"), false, "test");
    export_and_render(folder, 3);
  }
  write(dir / kMovie, "movie");
  write(dir / "images" / "my_notes.txt", "mine");
  write(dir / "frames" / "frame_0009.pov", "not recorded");
  try {
    FolderState::claim(dir, identity("scene-b"), false, "test");
    FAIL() << "another scene was let in";
  } catch (const FolderRefused& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("holds 3 frames of another scene"), std::string::npos) << what;
    EXPECT_NE(what.find("--force"), std::string::npos) << what;
  }
  EXPECT_TRUE(fs::exists(dir / final_image_name(Pass::image, 2)));  // refused: nothing touched

  ClaimNote note;
  const auto folder = FolderState::claim(dir, identity("scene-b"), true, "test", &note);
  EXPECT_NE(note.text.find("replaced 3 frames of another scene"), std::string::npos) << note.text;
  EXPECT_TRUE(folder.manifest().frames.empty());
  for (int n = 1; n <= 3; ++n) {
    EXPECT_FALSE(fs::exists(dir / final_image_name(Pass::image, n))) << n;
    EXPECT_FALSE(fs::exists(dir / frame_scene_name(Pass::image, n))) << n;
  }
  EXPECT_FALSE(fs::exists(dir / kMovie));
  EXPECT_EQ(read(dir / "images" / "my_notes.txt"), "mine");
  EXPECT_EQ(read(dir / "frames" / "frame_0009.pov"), "not recorded");
}

TEST(FolderClaim, OtherSettingsOfTheSameSceneAreRefusedSayingWhich) {
  const auto dir = testing::fresh_test_dir("claim_settings");
  { FolderState::claim(dir, identity("scene-a", 1), false, "test"); }
  auto bigger = identity("scene-a", 7);
  bigger.width = 320;
  bigger.masks = true;
  try {
    FolderState::claim(dir, bigger, false, "test");
    FAIL();
  } catch (const FolderRefused& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("this scene with other settings"), std::string::npos) << what;
    EXPECT_NE(what.find("seed 1 there, 7 here"), std::string::npos) << what;
    EXPECT_NE(what.find("size 64x36 there, 320x36 here"), std::string::npos) << what;
    EXPECT_NE(what.find("masks off there, on here"), std::string::npos) << what;
  }
}

TEST(FolderClaim, AShorterSceneRemovesTheFramesItNoLongerHas) {
  const auto dir = testing::fresh_test_dir("claim_shorter");
  auto folder = FolderState::claim(dir, identity(), false, "test");
  export_and_render(folder, 5);
  write(dir / "images" / "frame_0005.png.keep", "mine");
  folder.begin_export("shared", {1, 3}, 3);
  EXPECT_EQ(folder.manifest().frames.size(), 3U);
  for (int n : {4, 5}) {
    EXPECT_FALSE(fs::exists(dir / final_image_name(Pass::image, n))) << n;
    EXPECT_FALSE(fs::exists(dir / frame_scene_name(Pass::image, n))) << n;
  }
  EXPECT_TRUE(fs::exists(dir / final_image_name(Pass::image, 3)));
  EXPECT_EQ(read(dir / "images" / "frame_0005.png.keep"), "mine");
}

TEST(UpToDateRule, ARenderedImageIsUpToDateOnlyWhileItsBytesAreTheRecordedOnes) {
  const auto dir = testing::fresh_test_dir("rule_bytes");
  auto folder = FolderState::claim(dir, identity(), false, "test");
  export_and_render(folder, 5);
  develop_all(folder, 5);
  for (int n = 1; n <= 5; ++n)
    EXPECT_EQ(folder.decide(Pass::image, n, false), RenderReason::up_to_date);
  const auto image = [&](int n) { return dir / final_image_name(Pass::image, n); };
  fs::remove(image(1));
  fs::resize_file(image(2), 5);  // truncated
  fs::resize_file(image(3), 0);  // 0 bytes
  std::string bytes = read(image(4));
  bytes[3] ^= 1;  // same size, other bytes
  write(image(4), bytes);
  EXPECT_EQ(folder.decide(Pass::image, 1, false), RenderReason::file_missing);
  EXPECT_EQ(folder.decide(Pass::image, 2, false), RenderReason::file_truncated);
  EXPECT_EQ(folder.decide(Pass::image, 3, false), RenderReason::file_empty);
  EXPECT_EQ(folder.decide(Pass::image, 4, false), RenderReason::file_changed);
  EXPECT_EQ(folder.decide(Pass::image, 5, false), RenderReason::up_to_date);
  EXPECT_EQ(folder.decide(Pass::image, 5, true), RenderReason::forced);
  EXPECT_EQ(folder.verified_frames(), std::vector<int>{5});
  const auto plan = folder.plan({});
  EXPECT_EQ(plan.images, (std::vector<int>{1, 2, 3, 4}));
  EXPECT_EQ(plan.up_to_date, 1);
  EXPECT_EQ(plan.summary(),
            "4 to render: 1 image missing, 1 image empty, 1 image truncated, 1 image changed; 1 "
            "frames up to date");
  // A reopened folder (the next run) sees the same.
  const Manifest saved = folder.manifest();
  EXPECT_EQ(read_manifest(dir / kManifest).frames.at(4).image.file_hash,
            saved.frames.at(4).image.file_hash);
}

TEST(UpToDateRule, TransitionsGiveTheirReasons) {
  const auto dir = testing::fresh_test_dir("rule_transitions");
  auto folder = FolderState::claim(dir, identity(), false, "test");
  export_and_render(folder, 4);
  folder.frame_exported(1, "other inputs");
  folder.rendering(Pass::image, {2, 2});
  folder.failed(Pass::image, 3, "File 'x' line 1: Parse Error");
  EXPECT_EQ(folder.decide(Pass::image, 1, false), RenderReason::inputs_changed);
  EXPECT_EQ(folder.decide(Pass::image, 2, false), RenderReason::interrupted);
  EXPECT_EQ(folder.decide(Pass::image, 3, false), RenderReason::failed_before);
  EXPECT_EQ(folder.decide(Pass::image, 4, false), RenderReason::up_to_date);
  EXPECT_EQ(folder.decide(Pass::image, 9, false), RenderReason::not_exported);
  EXPECT_EQ(folder.decide(Pass::mask, 4, false), RenderReason::not_exported);  // no masks
  // The same inputs exported again: still up to date.
  folder.frame_exported(4, "shared+4");
  EXPECT_EQ(folder.decide(Pass::image, 4, false), RenderReason::up_to_date);
  // While an export rewrites a frame it vouches for nothing.
  folder.begin_export("shared", {4, 4}, 4);
  EXPECT_EQ(folder.decide(Pass::image, 4, false), RenderReason::not_exported);
  folder.frame_exported(4, "shared+4");
  EXPECT_EQ(folder.decide(Pass::image, 4, false), RenderReason::up_to_date);
  const auto m = read_manifest(dir / kManifest);
  EXPECT_EQ(m.frames[2].image.status, FrameStatus::failed);
  EXPECT_EQ(m.frames[2].image.error, "File 'x' line 1: Parse Error");
}

TEST(UpToDateRule, ChangedSharedFilesLeaveTheFramesOutsideTheRangeUnexported) {
  const auto dir = testing::fresh_test_dir("rule_shared");
  auto folder = FolderState::claim(dir, identity(), false, "test");
  export_and_render(folder, 4);
  folder.begin_export("shared v2", {1, 2}, 4);
  folder.frame_exported(1, "shared v2+1");
  folder.frame_exported(2, "shared v2+2");
  EXPECT_EQ(folder.decide(Pass::image, 1, false), RenderReason::inputs_changed);
  EXPECT_EQ(folder.decide(Pass::image, 3, false), RenderReason::not_exported);
  const auto plan = folder.plan({});
  EXPECT_EQ(plan.images, (std::vector<int>{1, 2}));
  EXPECT_NE(plan.summary().find("2 not exported"), std::string::npos) << plan.summary();
  EXPECT_TRUE(folder.verified_frames().empty());
}

// An export as export_frames does it, with the shared files written first.
void export_with_shared_files(FolderState& folder, int frames) {
  write(folder.dir() / "environment.inc", "#declare Lamp = 1;\n");
  write(folder.dir() / "scene.inc", "// scene\n");
  export_and_render(folder, frames);
}

TEST(HandEdits, AnEditedSharedFileChangesEveryFramesInputsATouchNone) {
  const auto dir = testing::fresh_test_dir("hand_edit_shared");
  {
    auto folder = FolderState::claim(dir, identity(), false, "test");
    export_with_shared_files(folder, 3);
  }
  // Touched only: the same bytes, a later time.
  fs::last_write_time(dir / "scene.inc",
                      fs::last_write_time(dir / "scene.inc") + std::chrono::seconds(5));
  {
    auto folder = FolderState::open(dir, "test");
    EXPECT_TRUE(folder.newly_edited_inputs().empty());
    EXPECT_TRUE(folder.plan({}).images.empty());
  }
  write(dir / "environment.inc", "#declare Lamp = 2;\n");  // the same size, other bytes
  auto folder = FolderState::open(dir, "test");
  EXPECT_EQ(folder.newly_edited_inputs(), std::vector<std::string>{"environment.inc"});
  for (int n = 1; n <= 3; ++n)
    EXPECT_EQ(folder.decide(Pass::image, n, false), RenderReason::inputs_changed) << n;
  // Rendered again from the edited file, the frames are up to date, also for the next run.
  for (int n = 1; n <= 3; ++n) folder.rendered(Pass::image, n, 0.5);
  EXPECT_EQ(folder.plan({}).images, std::vector<int>{});
  { FolderState moved = std::move(folder); }
  auto next = FolderState::open(dir, "test");
  EXPECT_TRUE(next.newly_edited_inputs().empty());
  EXPECT_EQ(next.hand_edited_inputs(), std::vector<std::string>{"environment.inc"});
  EXPECT_TRUE(next.plan({}).images.empty());
  // An export writes raintrace's own file back (the shared hash as first exported): the frames
  // it does not export are no longer exported, those it does are rendered again.
  write(dir / "environment.inc", "#declare Lamp = 1;\n");
  next.begin_export("shared", {1, 1}, 3);
  next.frame_exported(1, "shared+1");
  EXPECT_TRUE(next.hand_edited_inputs().empty());
  EXPECT_EQ(next.decide(Pass::image, 1, false), RenderReason::inputs_changed);
  EXPECT_EQ(next.decide(Pass::image, 2, false), RenderReason::not_exported);
}

TEST(HandEdits, AnEditedFrameChangesThatFramesInputsOnly) {
  const auto dir = testing::fresh_test_dir("hand_edit_frame");
  {
    auto folder = FolderState::claim(dir, identity(), false, "test");
    export_with_shared_files(folder, 3);
  }
  write(dir / frame_scene_name(Pass::image, 2), "frame 2, the light moved by hand");
  auto folder = FolderState::claim(dir, identity(), false, "test");  // a resumed run, too
  EXPECT_EQ(folder.newly_edited_inputs(),
            std::vector<std::string>{frame_scene_name(Pass::image, 2)});
  EXPECT_EQ(folder.decide(Pass::image, 1, false), RenderReason::up_to_date);
  EXPECT_EQ(folder.decide(Pass::image, 2, false), RenderReason::inputs_changed);
  EXPECT_EQ(folder.decide(Pass::image, 3, false), RenderReason::up_to_date);
}

// With puddles, each frame's text names its ripple map (ripples/ripple_NNNN.png), which the
// export writes just before the frame's text.
TEST(HandEdits, AnEditedRippleMapChangesThatFramesInputsOnlyAndGoesWithItsFrame) {
  const auto dir = testing::fresh_test_dir("hand_edit_ripples");
  {
    auto folder = FolderState::claim(dir, identity(), false, "test");
    folder.begin_export("shared", {1, 3}, 3);
    for (int n = 1; n <= 3; ++n) {
      write(dir / povgen::ripple_map_name(n), "ripple pixels " + std::to_string(n));
      write(dir / frame_scene_name(Pass::image, n), "frame " + std::to_string(n));
      folder.frame_exported(n, "shared+" + std::to_string(n));
      write(dir / final_image_name(Pass::image, n), "image bytes " + std::to_string(n));
      folder.rendered(Pass::image, n, 0.5);
    }
    folder.save();
  }
  write(dir / povgen::ripple_map_name(2), "ripple pixels X");  // the same size, other bytes
  auto folder = FolderState::open(dir, "test");
  EXPECT_EQ(folder.newly_edited_inputs(), std::vector<std::string>{povgen::ripple_map_name(2)});
  EXPECT_EQ(folder.decide(Pass::image, 1, false), RenderReason::up_to_date);
  EXPECT_EQ(folder.decide(Pass::image, 2, false), RenderReason::inputs_changed);
  EXPECT_EQ(folder.decide(Pass::image, 3, false), RenderReason::up_to_date);
  // A shorter scene takes the maps of the frames it no longer has, and their records.
  folder.begin_export("shared", {1, 2}, 2);
  EXPECT_FALSE(fs::exists(dir / povgen::ripple_map_name(3)));
  EXPECT_TRUE(fs::exists(dir / povgen::ripple_map_name(2)));
  for (const auto& r : folder.manifest().input_files) {
    EXPECT_NE(r.path, povgen::ripple_map_name(3));
  }
}

TEST(HandEdits, APictureRenderedByHandSinceTheEditIsAdoptedTheOthersRenderedAgain) {
  const auto dir = testing::fresh_test_dir("hand_edit_adopt");
  {
    auto folder = FolderState::claim(dir, identity(), false, "test");
    export_with_shared_files(folder, 2);
  }
  write(dir / "environment.inc", "#declare Lamp = 3; // brighter\n");
  // `povray scene.ini +SF2 +EF2` by hand after the edit: a whole image of the frame's size,
  // newer than every input.
  const auto image = dir / final_image_name(Pass::image, 2);
  OIIO::ImageBuf picture{OIIO::ImageSpec{64, 36, 3, OIIO::TypeDesc::HALF}};
  OIIO::ImageBufAlgo::fill(picture, {0.5f, 0.25f, 0.125f});
  ASSERT_TRUE(picture.write(image.string()));
  fs::last_write_time(image,
                      fs::last_write_time(dir / "environment.inc") + std::chrono::seconds(1));
  auto folder = FolderState::open(dir, "test");
  EXPECT_EQ(folder.decide(Pass::image, 1, false), RenderReason::inputs_changed);
  EXPECT_EQ(folder.decide(Pass::image, 2, false), RenderReason::up_to_date);
}

TEST(DevelopRule, APngIsCurrentOnlyForItsExrTheRunsDevelopHashAndItsRecordedBytes) {
  const auto dir = testing::fresh_test_dir("develop_rule");
  auto folder = FolderState::claim(dir, identity(), false, "test");
  export_and_render(folder, 6);
  folder.set_develop_hash("develop-a");
  for (int n = 1; n <= 6; ++n) EXPECT_EQ(folder.decide_develop(n), DevelopReason::new_frame);
  EXPECT_TRUE(folder.verified_frames().empty());  // an EXR alone is not a finished frame
  develop_all(folder, 6);
  EXPECT_EQ(folder.verified_frames(), (std::vector<int>{1, 2, 3, 4, 5, 6}));
  const auto png = [&](int n) { return dir / developed_image_name(n); };
  fs::remove(png(1));
  write(png(2), "edited");
  folder.develop_failed(3, "cannot write images/.tmp/frame_0003.png: No space left on device");
  // Frame 4 rendered again: its PNG no longer shows its EXR.
  write(dir / final_image_name(Pass::image, 4), "another EXR");
  folder.rendered(Pass::image, 4, 0.5);
  // Frame 5's EXR is gone: it renders again, and develops after.
  fs::remove(dir / final_image_name(Pass::image, 5));
  EXPECT_EQ(folder.decide_develop(1), DevelopReason::file_missing);
  EXPECT_EQ(folder.decide_develop(2), DevelopReason::file_changed);
  EXPECT_EQ(folder.decide_develop(3), DevelopReason::failed_before);
  EXPECT_EQ(folder.decide_develop(4), DevelopReason::new_frame);
  EXPECT_EQ(folder.decide_develop(5), DevelopReason::not_rendered);
  EXPECT_EQ(folder.decide_develop(6), DevelopReason::up_to_date);
  const auto plan = folder.plan({});
  EXPECT_EQ(plan.images, std::vector<int>{5});
  EXPECT_EQ(plan.develops, (std::vector<int>{1, 2, 3, 4}));
  EXPECT_EQ(plan.up_to_date, 1);
  EXPECT_EQ(plan.summary(),
            "1 to render: 1 image missing; 4 to develop only: 1 not developed, 1 develop failed "
            "before, 1 picture missing, 1 picture changed; 1 frames up to date");
  EXPECT_EQ(read_manifest(dir / kManifest).frames[2].developed.error,
            "cannot write images/.tmp/frame_0003.png: No space left on device");
}

TEST(DevelopRule, OtherDevelopSettingsRedevelopEveryFrameAndRenderNone) {
  const auto dir = testing::fresh_test_dir("develop_settings");
  auto folder = FolderState::claim(dir, identity(), false, "test");
  export_and_render(folder, 3);
  develop_all(folder, 3, "exposure 0");
  // The next run develops with other settings: a new develop hash.
  folder.set_develop_hash("exposure -1");
  const auto plan = folder.plan({});
  EXPECT_TRUE(plan.images.empty());
  EXPECT_EQ(plan.develops, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(plan.develop_reasons.at(DevelopReason::settings_changed), 3);
  EXPECT_TRUE(folder.verified_frames().empty());
  develop_all(folder, 3, "exposure -1");
  EXPECT_TRUE(folder.plan({}).develops.empty());
  EXPECT_EQ(folder.plan({}).up_to_date, 3);
}

TEST(DevelopRule, TheHashCoversSettingsFieldOfViewSeedAndTheTransformsResponse) {
  film::RgbImage response(2, 1, 0.5f);
  const DevelopSpec spec;
  const std::string base = develop_hash(spec, 1, response);
  EXPECT_EQ(develop_hash(spec, 1, response), base);
  DevelopSpec other = spec;
  other.settings.exposure_ev = -1;
  EXPECT_NE(develop_hash(other, 1, response), base);
  other = spec;
  other.settings.look = film::Look::high_contrast;
  EXPECT_NE(develop_hash(other, 1, response), base);
  other = spec;
  other.fov_deg = 40;
  EXPECT_NE(develop_hash(other, 1, response), base);
  EXPECT_NE(develop_hash(spec, 2, response), base);
  response.pixels[4] = 0.51f;  // another blender-data that moves one value
  EXPECT_NE(develop_hash(spec, 1, response), base);
}

TEST(FolderClaim, AFolderOfAnOlderFormatIsRefusedUnlessForced) {
  const auto dir = testing::fresh_test_dir("claim_old_format");
  Manifest old;
  old.raintrace_version = "0.1.0";
  old.format = 1;
  old.identity = identity();
  FrameEntry f;
  f.number = 1;
  f.image.path = "images/frame_0001.png";
  old.frames.push_back(f);
  write(dir / "images/frame_0001.png", "an 8-bit frame");
  write_manifest(dir / kManifest, old);
  try {
    FolderState::claim(dir, identity(), false, "test");
    FAIL() << "an older folder was resumed";
  } catch (const FolderRefused& e) {
    EXPECT_NE(std::string{e.what()}.find("older raintrace"), std::string::npos) << e.what();
  }
  EXPECT_THROW(FolderState::open(dir, "test"), FolderRefused);
  ClaimNote note;
  const auto folder = FolderState::claim(dir, identity(), true, "test", &note);
  EXPECT_EQ(folder.manifest().format, kFolderFormat);
  EXPECT_FALSE(fs::exists(dir / "images/frame_0001.png"));
  EXPECT_NE(note.text.find("older raintrace"), std::string::npos) << note.text;
}

TEST(Assembly, TheKeyChangesWithTheFramesAndTheirBytes) {
  const auto dir = testing::fresh_test_dir("assembly_key");
  auto folder = FolderState::claim(dir, identity(), false, "test");
  export_and_render(folder, 3);
  develop_all(folder, 3);
  const std::string all = assembly_key(folder, {1, 2, 3});
  EXPECT_EQ(assembly_key(folder, {1, 2, 3}), all);
  EXPECT_NE(assembly_key(folder, {1, 2}), all);
  write(dir / developed_image_name(2), "another picture");
  folder.developed(2, 0.1);
  EXPECT_NE(assembly_key(folder, {1, 2, 3}), all);
}

}  // namespace
}  // namespace raintrace::output
