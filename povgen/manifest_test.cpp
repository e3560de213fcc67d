// manifest.json: round trip, atomic write, errors, and the FNV-1a hash's published values.
#include "povgen/manifest.h"

#include <gtest/gtest.h>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace raintrace::povgen {
namespace {

Manifest sample() {
  Manifest m;
  m.raintrace_version = "0.1.0";
  m.scene_hash = "0123456789abcdef";
  m.seed = 18446744073709551615ULL;  // the full 64-bit range survives JSON
  m.width = 640;
  m.height = 360;
  m.fps = 23.976;
  m.quality = "final";
  FrameEntry f;
  f.number = 2;
  f.scene = "frames/frame_0002.pov";
  f.image = "images/frame_0002.png";
  f.input_hash = "aaaa";
  f.status = "failed";
  f.rendered_hash = "bbbb";
  f.render_seconds = 1.25;
  f.error = "File 'x.pov' line 5: Parse Error: \"quoted\"\nsecond line";
  m.frames.push_back(f);
  return m;
}

TEST(Manifest, RoundTripsThroughJson) {
  const Manifest m = sample();
  const Manifest back = manifest_from_json(to_json(m));
  EXPECT_EQ(back.raintrace_version, m.raintrace_version);
  EXPECT_EQ(back.scene_hash, m.scene_hash);
  EXPECT_EQ(back.seed, m.seed);
  EXPECT_EQ(back.width, 640);
  EXPECT_EQ(back.height, 360);
  EXPECT_DOUBLE_EQ(back.fps, 23.976);
  EXPECT_EQ(back.quality, "final");
  ASSERT_EQ(back.frames.size(), 1u);
  EXPECT_EQ(back.frames[0].number, 2);
  EXPECT_EQ(back.frames[0].scene, "frames/frame_0002.pov");
  EXPECT_EQ(back.frames[0].image, "images/frame_0002.png");
  EXPECT_EQ(back.frames[0].input_hash, "aaaa");
  EXPECT_EQ(back.frames[0].status, "failed");
  EXPECT_EQ(back.frames[0].rendered_hash, "bbbb");
  EXPECT_DOUBLE_EQ(back.frames[0].render_seconds, 1.25);
  EXPECT_EQ(back.frames[0].error, m.frames[0].error);
  EXPECT_EQ(to_json(back), to_json(m));
}

TEST(Manifest, BadJsonThrows) {
  EXPECT_THROW(manifest_from_json("{"), std::runtime_error);
  EXPECT_THROW(manifest_from_json("[]"), std::runtime_error);
  EXPECT_THROW(manifest_from_json(R"({"frames": 3})"), std::runtime_error);
  EXPECT_THROW(manifest_from_json(R"({"width": "wide"})"), std::runtime_error);
}

TEST(Manifest, WriteIsAtomicAndReadable) {
  const auto dir = std::filesystem::temp_directory_path() / "raintrace_manifest_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto path = dir / "manifest.json";
  write_manifest(path, sample());
  EXPECT_FALSE(std::filesystem::exists(dir / "manifest.json.tmp"));
  EXPECT_EQ(read_manifest(path).frames.at(0).status, "failed");
  Manifest changed = sample();
  changed.frames[0].status = "rendered";
  write_manifest(path, changed);
  EXPECT_EQ(read_manifest(path).frames.at(0).status, "rendered");
  EXPECT_THROW(read_manifest(dir / "missing.json"), std::runtime_error);
  std::filesystem::remove_all(dir);
}

TEST(Manifest, ContentHashIsFnv1a64) {
  // Published FNV-1a 64-bit test vectors (Fowler/Noll/Vo reference test suite).
  EXPECT_EQ(content_hash(""), "cbf29ce484222325");
  EXPECT_EQ(content_hash("a"), "af63dc4c8601ec8c");
  EXPECT_EQ(content_hash("foobar"), "85944171f73967e8");
  EXPECT_NE(content_hash("frame 1"), content_hash("frame 2"));
}

TEST(Manifest, HashingInPiecesEqualsHashingAtOnce) {
  ContentHasher hasher;
  hasher.update("foo");
  hasher.update("");
  hasher.update("bar");
  EXPECT_EQ(hasher.hex(), "85944171f73967e8");
}

}  // namespace
}  // namespace raintrace::povgen
