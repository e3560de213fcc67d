// Only whole images at the right size count as finished.
#include "output/image_check.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>
#include <fstream>
#include <sstream>

#include "output/test_dir.h"
#include "povgen/content_hash.h"

namespace raintrace::output {
namespace {

TEST(ImageIsComplete, AcceptsWholeImageRejectsTruncatedWrongSizeAndMissing) {
  const auto dir = testing::fresh_test_dir("check");
  OIIO::ImageBuf img{OIIO::ImageSpec{64, 36, 3, OIIO::TypeDesc::UINT8}};
  OIIO::ImageBufAlgo::noise(img, "uniform", 0.0f, 1.0f);  // incompressible, so the file is big
  ASSERT_TRUE(img.write((dir / "whole.png").string()));
  EXPECT_TRUE(image_is_complete(dir / "whole.png", 64, 36));
  std::string why;
  EXPECT_FALSE(image_is_complete(dir / "whole.png", 64, 37, &why));
  EXPECT_EQ(why, "64x36 instead of 64x37");
  EXPECT_FALSE(image_is_complete(dir / "missing.png", 64, 36, &why));
  EXPECT_EQ(why, "missing");

  // The file as a killed writer leaves it: every prefix is rejected.
  std::ifstream in{dir / "whole.png", std::ios::binary};
  std::ostringstream bytes;
  bytes << in.rdbuf();
  const std::string whole = bytes.str();
  for (std::size_t cut : {whole.size() / 4, whole.size() / 2, whole.size() - 1}) {
    std::ofstream{dir / "cut.png", std::ios::binary} << whole.substr(0, cut);
    EXPECT_FALSE(image_is_complete(dir / "cut.png", 64, 36)) << cut;
  }
  // Even with a valid ending glued on, a missing middle fails the full decode.
  std::ofstream{dir / "hole.png", std::ios::binary} << whole.substr(0, whole.size() / 2)
                                                    << whole.substr(whole.size() - 12);
  EXPECT_FALSE(image_is_complete(dir / "hole.png", 64, 36));
}

TEST(ImageIsComplete, JudgesAFileReplacedAtTheSamePathByItsNewBytes) {
  // POV-Ray writes every frame of a run to the same temporary names, and a re-render replaces
  // a frame's EXR: an answer remembered from an earlier file at that path would be wrong.
  const auto dir = testing::fresh_test_dir("check_replaced");
  const auto path = dir / "frame.exr";
  auto write_exr = [&](int width, int height) {
    OIIO::ImageBuf img{OIIO::ImageSpec{width, height, 3, OIIO::TypeDesc::HALF}};
    OIIO::ImageBufAlgo::fill(img, {0.5f, 0.25f, 0.125f});
    const auto temp = dir / "next.exr";
    ASSERT_TRUE(img.write(temp.string()));
    std::filesystem::rename(temp, path);
  };
  write_exr(64, 37);
  std::string why;
  EXPECT_FALSE(image_is_complete(path, 64, 36, &why));
  EXPECT_EQ(why, "64x37 instead of 64x36");
  write_exr(64, 36);
  EXPECT_TRUE(image_is_complete(path, 64, 36, &why)) << why;
  std::ofstream{path, std::ios::binary};  // as POV-Ray leaves it just after opening it
  EXPECT_FALSE(image_is_complete(path, 64, 36, &why));
  EXPECT_EQ(why.rfind("unreadable", 0), 0U) << why;
}

TEST(FileFacts, AreTheSizeAndContentHashOfTheBytes) {
  const auto dir = testing::fresh_test_dir("facts");
  EXPECT_FALSE(file_facts(dir / "missing.png"));
  std::ofstream{dir / "a.bin", std::ios::binary} << "foobar";
  const auto facts = file_facts(dir / "a.bin");
  ASSERT_TRUE(facts);
  EXPECT_EQ(facts->size, 6U);
  EXPECT_EQ(facts->hash, povgen::content_hash("foobar"));
  // Bigger than the read buffer: the same as hashing the whole at once.
  const std::string big(200000, 'x');
  std::ofstream{dir / "big.bin", std::ios::binary} << big;
  EXPECT_EQ(file_facts(dir / "big.bin")->hash, povgen::content_hash(big));
  std::ofstream{dir / "empty.bin", std::ios::binary};
  EXPECT_EQ(file_facts(dir / "empty.bin")->size, 0U);
}

}  // namespace
}  // namespace raintrace::output
