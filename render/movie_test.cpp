// ffmpeg command lines, and a real encode when ffmpeg is installed.
#include "render/movie.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>
#include <algorithm>

#include "render/povray_command.h"
#include "render/process.h"
#include "render/test_folder.h"

namespace raintrace::render {
namespace {

bool has(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

TEST(MovieArgv, Mp4IsH264Yuv420WithEvenSize) {
  const auto argv = mp4_argv(24, {5, 3, 4}, "x.mp4");
  EXPECT_TRUE(has(argv, "libx264"));
  EXPECT_TRUE(has(argv, "yuv420p"));
  EXPECT_TRUE(has(argv, "scale=trunc(iw/2)*2:trunc(ih/2)*2"));
  const auto start = std::find(argv.begin(), argv.end(), "-start_number");
  ASSERT_NE(start, argv.end());
  EXPECT_EQ(*(start + 1), "5");
  // Exactly the frames given, even when later images exist.
  const auto count = std::find(argv.begin(), argv.end(), "-frames:v");
  ASSERT_NE(count, argv.end());
  EXPECT_EQ(*(count + 1), "3");
  EXPECT_EQ(argv.back(), "x.mp4");
}

TEST(MovieArgv, GifUsesAGeneratedPalette) {
  const auto argv = gif_argv(12, {1, 2, 4}, "x.gif");
  const auto graph = std::find(argv.begin(), argv.end(), "-filter_complex");
  ASSERT_NE(graph, argv.end());
  EXPECT_NE((graph + 1)->find("palettegen"), std::string::npos);
  EXPECT_NE((graph + 1)->find("paletteuse"), std::string::npos);
}

TEST(Movies, OddSizedFramesBecomeAPlayableMp4AndGif) {
  if (!find_program("ffmpeg") || !find_program("ffprobe")) {
    GTEST_SKIP() << "ffmpeg not installed (apt-get install ffmpeg)";
  }
  const auto dir = testing::fresh_test_dir("movie");
  std::filesystem::create_directories(dir / "images");
  for (int f = 1; f <= 5; ++f) {
    OIIO::ImageBuf img{OIIO::ImageSpec{33, 17, 3, OIIO::TypeDesc::UINT8}};
    const float c[3] = {static_cast<float>(f) / 4.0f, 0.5f, 0.2f};
    OIIO::ImageBufAlgo::fill(img, c);
    ASSERT_TRUE(img.write((dir / developed_image_name(f)).string()));
  }
  const auto result = make_movies(dir, 24, {1, 4, 4});  // a fifth image exists: not shown
  EXPECT_TRUE(result.warning.empty()) << result.warning;
  ASSERT_FALSE(result.mp4.empty());
  ASSERT_FALSE(result.gif.empty());
  ProcessSpec probe;
  probe.argv = {"ffprobe",
                "-v",
                "error",
                "-count_frames",
                "-select_streams",
                "v:0",
                "-show_entries",
                "stream=width,height,pix_fmt,nb_read_frames",
                "-of",
                "csv=p=0",
                result.mp4.string()};
  // 33×17 rounds down to even 32×16; all 4 frames are in the stream.
  EXPECT_EQ(run_capture(probe).out, "32,16,yuv420p,4\n");
}

}  // namespace
}  // namespace raintrace::render
