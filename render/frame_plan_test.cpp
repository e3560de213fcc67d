// Resume rules and span cutting.
#include "render/frame_plan.h"

#include <gtest/gtest.h>
#include <fstream>

#include "render/test_folder.h"

namespace raintrace::render {
namespace {

std::vector<int> iota(int first, int last) {
  std::vector<int> v;
  for (int i = first; i <= last; ++i) v.push_back(i);
  return v;
}

TEST(SplitIntoSpans, GivesEachJobAboutTwoSpansCappedAtMaxSpan) {
  // 48 frames, 2 jobs: ceil(48 / 4) = 12 frames per span → 4 spans.
  const auto spans = split_into_spans(iota(1, 48), 2, 16);
  ASSERT_EQ(spans.size(), 4U);
  EXPECT_EQ(spans[0].first, 1);
  EXPECT_EQ(spans[0].last, 12);
  EXPECT_EQ(spans[3].last, 48);
  // 1000 frames: capped at 12 → ceil(1000 / 12) = 84 spans.
  EXPECT_EQ(split_into_spans(iota(1, 1000), 2, 12).size(), 84U);
}

TEST(SplitIntoSpans, NeverBridgesAGap) {
  const auto spans = split_into_spans({1, 2, 3, 7, 8}, 1, 16);
  ASSERT_EQ(spans.size(), 2U);
  EXPECT_EQ(spans[0].last, 3);
  EXPECT_EQ(spans[1].first, 7);
  EXPECT_EQ(spans[1].last, 8);
}

TEST(SplitIntoSpans, CoversEveryFrameExactlyOnce) {
  const auto frames = std::vector<int>{2, 3, 4, 5, 9, 10, 11, 20, 21, 22, 23, 24, 25, 26, 40};
  std::vector<int> covered;
  for (const auto& s : split_into_spans(frames, 3, 4)) {
    EXPECT_LE(s.count(), 4);
    for (int f = s.first; f <= s.last; ++f) covered.push_back(f);
  }
  EXPECT_EQ(covered, frames);
}

TEST(FramesNeedingRender, SkipsOnlyUpToDateFramesWhoseImageExists) {
  const auto dir = testing::fresh_test_dir("plan");
  testing::write_test_folder(dir, {.frames = 5});
  auto manifest = povgen::read_manifest(dir / "manifest.json");
  EXPECT_EQ(frames_needing_render(manifest, dir, false, std::nullopt), iota(1, 5));

  std::filesystem::create_directories(dir / "images");
  for (int f : {1, 2, 3, 4}) {
    std::ofstream{dir / final_image_name(Pass::image, f)} << "x";
    manifest.frames[f - 1].status = "rendered";
    manifest.frames[f - 1].rendered_hash = manifest.frames[f - 1].input_hash;
  }
  manifest.frames[1].rendered_hash = "stale";  // frame 2's inputs changed since its render
  std::filesystem::remove(dir / final_image_name(Pass::image, 3));  // frame 3's image is lost
  EXPECT_EQ(frames_needing_render(manifest, dir, false, std::nullopt), (std::vector<int>{2, 3, 5}));
  EXPECT_EQ(frames_needing_render(manifest, dir, false, FrameSpan{3, 4}), (std::vector<int>{3}));
  EXPECT_EQ(frames_needing_render(manifest, dir, true, std::nullopt), iota(1, 5));
}

}  // namespace
}  // namespace raintrace::render
