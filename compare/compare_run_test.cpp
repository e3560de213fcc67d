// Whole comparisons on files written to a temporary folder: matching, missing frames, unusable
// input, difference images and thread-count independence.
#include "compare/compare_run.h"

#include <gtest/gtest.h>

#include <fstream>

#include "compare/image_io.h"
#include "compare/test_files.h"

namespace raintrace::compare {
namespace {

namespace fs = std::filesystem;
using testing_support::TempDir;

Image pattern(int w, int h, int shift) {
  Image img(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) img.at(x, y, c) = float((x + y * 3 + c + shift) % 256) / 255.0f;
  return img;
}

TEST(CompareRun, ReadWriteRoundTripKeepsEightBitValues) {
  TempDir tmp;
  const Image a = pattern(16, 8, 0);
  write_image(tmp.path() / "a.png", a);
  const Image back = read_image(tmp.path() / "a.png");
  ASSERT_EQ(back.width, 16);
  ASSERT_EQ(back.channels, 3);
  // Values are k/255, so 8 bits hold them; only float rounding of k/255 (k·(1/255) in OIIO vs
  // our k/255) may differ, by ~1 ulp ≈ 6e-8.
  EXPECT_LT(compute_metrics(a, back).max_error, 1e-7);
}

TEST(CompareRun, TwoImagesGiveOneFrame) {
  TempDir tmp;
  write_image(tmp.path() / "a.png", pattern(16, 8, 0));
  Image b = pattern(16, 8, 0);
  b.at(3, 4, 1) = 1.0f;
  write_image(tmp.path() / "b.png", b);
  const auto report = compare_paths(tmp.path() / "a.png", tmp.path() / "b.png");
  ASSERT_EQ(report.frames.size(), 1u);
  EXPECT_FALSE(report.folders);
  EXPECT_EQ(report.frames[0].metrics.max_x, 3);
  EXPECT_EQ(report.frames[0].metrics.max_y, 4);
  EXPECT_TRUE(report.any_failed());
}

TEST(CompareRun, FoldersMatchByNameAndReportMissingFramesAsFailures) {
  TempDir tmp;
  const fs::path ra = tmp.path() / "ref", rb = tmp.path() / "out";
  fs::create_directories(ra);
  fs::create_directories(rb);
  for (int i = 1; i <= 3; ++i)
    write_image(ra / ("frame_000" + std::to_string(i) + ".png"), pattern(8, 8, i));
  for (int i = 2; i <= 4; ++i)
    write_image(rb / ("frame_000" + std::to_string(i) + ".png"), pattern(8, 8, i));
  std::ofstream(ra / "notes.txt") << "not an image";
  const auto report = compare_paths(ra, rb);
  ASSERT_EQ(report.frames.size(), 4u);
  EXPECT_EQ(report.frames[0].status, FrameStatus::missing_b);
  EXPECT_EQ(report.frames[1].status, FrameStatus::compared);
  EXPECT_EQ(report.frames[1].metrics.verdict, Verdict::pass);
  EXPECT_EQ(report.frames[3].status, FrameStatus::missing_a);
  EXPECT_EQ(report.frames[3].verdict_string(), "MISSING");
  EXPECT_TRUE(report.any_failed());
  EXPECT_FALSE(report.any_error());
}

TEST(CompareRun, SizeMismatchAndUnreadableFilesAreErrorsNamingTheFiles) {
  TempDir tmp;
  const fs::path ra = tmp.path() / "ref", rb = tmp.path() / "out";
  fs::create_directories(ra);
  fs::create_directories(rb);
  write_image(ra / "a.png", pattern(8, 8, 0));
  write_image(rb / "a.png", pattern(9, 8, 0));
  write_image(ra / "b.png", pattern(8, 8, 0));
  std::ofstream(rb / "b.png") << "garbage";
  write_image(ra / "c.png", pattern(8, 8, 0));
  write_image(rb / "c.png", pattern(8, 8, 0));
  const auto report = compare_paths(ra, rb);
  ASSERT_EQ(report.frames.size(), 3u);
  EXPECT_EQ(report.frames[0].status, FrameStatus::error);
  EXPECT_NE(report.frames[0].error.find("8x8x3"), std::string::npos) << report.frames[0].error;
  EXPECT_NE(report.frames[0].error.find("9x8x3"), std::string::npos) << report.frames[0].error;
  EXPECT_NE(report.frames[0].error.find((rb / "a.png").string()), std::string::npos);
  EXPECT_EQ(report.frames[1].status, FrameStatus::error);
  EXPECT_NE(report.frames[1].error.find((rb / "b.png").string()), std::string::npos);
  EXPECT_EQ(report.frames[2].metrics.verdict, Verdict::pass);  // the good frame still compared
  EXPECT_TRUE(report.any_error());
}

TEST(CompareRun, FolderAgainstFileAndMissingPathsThrow) {
  TempDir tmp;
  write_image(tmp.path() / "a.png", pattern(8, 8, 0));
  EXPECT_THROW(compare_paths(tmp.path(), tmp.path() / "a.png"), std::runtime_error);
  EXPECT_THROW(compare_paths(tmp.path() / "a.png", tmp.path() / "nope.png"), std::runtime_error);
}

TEST(CompareRun, ResultsDoNotDependOnThreadCountAndDiffsAreWritten) {
  TempDir tmp;
  const fs::path ra = tmp.path() / "ref", rb = tmp.path() / "out";
  fs::create_directories(ra);
  fs::create_directories(rb);
  for (int i = 0; i < 7; ++i) {
    const std::string name = "f" + std::to_string(i) + ".png";
    write_image(ra / name, pattern(24, 16, i));
    write_image(rb / name, pattern(24, 16, i + (i % 3)));
  }
  CompareOptions one;
  one.threads = 1;
  CompareOptions two;
  two.threads = 2;
  two.diff_dir = tmp.path() / "diff";
  const auto r1 = compare_paths(ra, rb, one), r2 = compare_paths(ra, rb, two);
  ASSERT_EQ(r1.frames.size(), 7u);
  ASSERT_EQ(r2.frames.size(), 7u);
  for (std::size_t i = 0; i < 7; ++i) {
    EXPECT_EQ(r1.frames[i].name, r2.frames[i].name);
    EXPECT_EQ(r1.frames[i].metrics.rmse, r2.frames[i].metrics.rmse);
    EXPECT_EQ(r1.frames[i].metrics.ssim, r2.frames[i].metrics.ssim);
    ASSERT_TRUE(fs::exists(r2.frames[i].diff_image)) << r2.frames[i].diff_image;
    const Image diff = read_image(r2.frames[i].diff_image);
    EXPECT_EQ(diff.width, 24);
    EXPECT_EQ(diff.height, 16 + 16);  // the scale bar under it
  }
}

}  // namespace
}  // namespace raintrace::compare
