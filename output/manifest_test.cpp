// manifest.json: round trip, atomic write, and what is not a raintrace manifest.
#include "output/manifest.h"

#include <gtest/gtest.h>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "output/test_dir.h"

namespace raintrace::output {
namespace {

Manifest sample() {
  Manifest m;
  m.raintrace_version = "0.1.0";
  m.identity.scene_hash = "0123456789abcdef";
  m.identity.seed = 18446744073709551615ULL;  // the full 64-bit range survives JSON
  m.identity.width = 640;
  m.identity.height = 360;
  m.identity.fps = 23.976;
  m.identity.quality = povgen::Quality::final;
  m.identity.masks = true;
  m.shared_hash = "5555";
  m.frame_count = 48;
  m.movie_source = "mmmm";
  m.contact_sheet_source = "cccc";
  FrameEntry f;
  f.number = 2;
  f.input_hash = "aaaa";
  f.image.scene = "frames/frame_0002.pov";
  f.image.path = "images/frame_0002.exr";
  f.image.status = FrameStatus::failed;
  f.image.rendered_hash = "bbbb";
  f.image.seconds = 1.25;
  f.image.error = "File 'x.pov' line 5: Parse Error: \"quoted\"\nsecond line";
  PictureRecord mask;
  mask.scene = "frames/mask_0002.pov";
  mask.path = "images/mask_0002.png";
  mask.status = FrameStatus::rendered;
  mask.rendered_hash = "aaaa";
  mask.size = 5000000000ULL;  // past 32 bits
  mask.file_hash = "dddd";
  f.mask = mask;
  f.developed.path = "images/frame_0002.png";
  f.developed.develop_hash = "eeee";
  f.developed.source_hash = "ffff";
  f.developed.size = 123456;
  f.developed.file_hash = "9999";
  f.developed.seconds = 0.125;
  m.develop.settings = {.exposure_ev = -1.5,
                        .white_balance_k = 3200,
                        .view = film::View::filmic,
                        .look = film::Look::high_contrast,
                        .bloom = 0.1,
                        .softness = 1.25,
                        .grain = 0,
                        .sensor_noise = 0.07,
                        .vignette = 0.25,
                        .aperture_blades = 7};
  m.develop.fov_deg = 42.5;
  m.develop.aperture_m = 0.0035;
  m.frames.push_back(f);
  m.input_files.push_back({"environment.inc", 100834, 1764817932123456789LL, "7777", true});
  return m;
}

TEST(Manifest, RoundTripsThroughJson) {
  const Manifest m = sample();
  const Manifest back = manifest_from_json(to_json(m));
  EXPECT_EQ(back.raintrace_version, m.raintrace_version);
  EXPECT_EQ(back.format, kFolderFormat);
  EXPECT_EQ(back.identity, m.identity);
  EXPECT_EQ(back.develop, m.develop);
  EXPECT_EQ(back.shared_hash, "5555");
  EXPECT_EQ(back.frame_count, 48);
  EXPECT_EQ(back.movie_source, "mmmm");
  EXPECT_EQ(back.contact_sheet_source, "cccc");
  ASSERT_EQ(back.frames.size(), 1u);
  const FrameEntry& f = back.frames[0];
  EXPECT_EQ(f.number, 2);
  EXPECT_EQ(f.input_hash, "aaaa");
  EXPECT_EQ(f.image.scene, "frames/frame_0002.pov");
  EXPECT_EQ(f.image.path, "images/frame_0002.exr");
  EXPECT_EQ(f.developed.path, "images/frame_0002.png");
  EXPECT_EQ(f.developed.develop_hash, "eeee");
  EXPECT_EQ(f.developed.source_hash, "ffff");
  EXPECT_EQ(f.developed.size, 123456U);
  EXPECT_EQ(f.developed.file_hash, "9999");
  EXPECT_EQ(f.image.status, FrameStatus::failed);
  EXPECT_EQ(f.image.rendered_hash, "bbbb");
  EXPECT_DOUBLE_EQ(f.image.seconds, 1.25);
  EXPECT_EQ(f.image.error, m.frames[0].image.error);
  ASSERT_TRUE(f.mask);
  EXPECT_EQ(f.mask->status, FrameStatus::rendered);
  EXPECT_EQ(f.mask->size, 5000000000ULL);
  EXPECT_EQ(f.mask->file_hash, "dddd");
  EXPECT_EQ(back.input_files, m.input_files);  // nanosecond times past 53 bits survive too
  EXPECT_EQ(to_json(back), to_json(m));
}

TEST(Manifest, AManifestWithoutAFormatIsOfTheFirstFormat) {
  // Written by raintrace before frames were HDR: no "folder_format", no "develop".
  const Manifest m = manifest_from_json(R"({"raintrace_version": "0.1.0", "frames": []})");
  EXPECT_EQ(m.format, 1);
  EXPECT_EQ(m.develop, DevelopSpec{});
  EXPECT_THROW(manifest_from_json(R"({"raintrace_version": "x", "develop": {"look": "vivid"}})"),
               std::runtime_error);
  EXPECT_THROW(manifest_from_json(R"({"raintrace_version": "x", "develop": {"bloom": 3}})"),
               std::runtime_error);
  // Blades need the opening their spikes are drawn for.
  EXPECT_THROW(
      manifest_from_json(R"({"raintrace_version": "x", "develop": {"aperture_blades": 6}})"),
      std::runtime_error);
}

TEST(Manifest, StatusesAreReadableWordsInTheJson) {
  const std::string json = to_json(sample());
  EXPECT_NE(json.find(R"("status": "failed")"), std::string::npos) << json;
  EXPECT_NE(json.find(R"("status": "rendered")"), std::string::npos) << json;
  for (const auto s : {FrameStatus::exported, FrameStatus::rendering, FrameStatus::rendered,
                       FrameStatus::failed}) {
    EXPECT_EQ(parse_frame_status(to_string(s)), s);
  }
  EXPECT_FALSE(parse_frame_status("done"));
}

TEST(Manifest, WhatIsNotARaintraceManifestThrows) {
  EXPECT_THROW(manifest_from_json("{"), std::runtime_error);
  EXPECT_THROW(manifest_from_json("[]"), std::runtime_error);
  // Another tool's manifest.json: no raintrace_version.
  EXPECT_THROW(manifest_from_json(R"({"name": "my-app", "version": "1.0"})"), std::runtime_error);
  EXPECT_THROW(manifest_from_json(R"({"raintrace_version": "1", "frames": 3})"),
               std::runtime_error);
  EXPECT_THROW(manifest_from_json(R"({"raintrace_version": "1", "width": "wide"})"),
               std::runtime_error);
  EXPECT_THROW(
      manifest_from_json(R"({"raintrace_version": "1", "frames": [{"number": 1, "status": "x"}]})"),
      std::runtime_error);
}

TEST(Manifest, FrameDigitsComeFromTheImageNames) {
  Manifest m = sample();
  EXPECT_EQ(frame_digits(m), 4);
  m.frames[0].image.path = "images/frame_00002.png";
  EXPECT_EQ(frame_digits(m), 5);
  m.frames.clear();
  m.frame_count = 123456;
  EXPECT_EQ(frame_digits(m), 6);
}

TEST(Manifest, WriteIsAtomicAndReadable) {
  const auto dir = testing::fresh_test_dir("manifest");
  const auto path = dir / "manifest.json";
  write_manifest(path, sample());
  EXPECT_FALSE(std::filesystem::exists(dir / "manifest.json.tmp"));
  EXPECT_EQ(read_manifest(path).frames.at(0).image.status, FrameStatus::failed);
  Manifest changed = sample();
  changed.frames[0].image.status = FrameStatus::rendered;
  write_manifest(path, changed);
  EXPECT_EQ(read_manifest(path).frames.at(0).image.status, FrameStatus::rendered);
  EXPECT_THROW(read_manifest(dir / "missing.json"), std::system_error);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace raintrace::output
