// Contact sheet layout and frame choice.
#include "render/contact_sheet.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>

#include "render/povray_command.h"
#include "render/test_folder.h"

namespace raintrace::render {
namespace {

TEST(PickEvenly, KeepsFirstAndLastAndSpacesTheRest) {
  std::vector<int> frames;
  for (int f = 1; f <= 48; ++f) frames.push_back(f);
  // Indices round(i·47/3) for i = 0..3: 0, 16, 31, 47 → frames 1, 17, 32, 48.
  EXPECT_EQ(pick_evenly(frames, 4), (std::vector<int>{1, 17, 32, 48}));
  EXPECT_EQ(pick_evenly({3, 4}, 9), (std::vector<int>{3, 4}));
  EXPECT_EQ(pick_evenly(frames, 1), (std::vector<int>{1}));
}

TEST(ContactSheet, PlacesEachFrameInItsGridCell) {
  const auto dir = testing::fresh_test_dir("sheet");
  std::filesystem::create_directories(dir / "images");
  // Five 20×10 frames of distinct flat colours: grid of ceil(sqrt 5) = 3 columns, 2 rows.
  for (int f = 1; f <= 5; ++f) {
    OIIO::ImageBuf img{OIIO::ImageSpec{20, 10, 3, OIIO::TypeDesc::UINT8}};
    const float c[3] = {static_cast<float>(f) / 5.0f, 0.0f, 1.0f - static_cast<float>(f) / 5.0f};
    OIIO::ImageBufAlgo::fill(img, c);
    ASSERT_TRUE(img.write((dir / developed_image_name(f)).string()));
  }
  const auto result = make_contact_sheet(dir, {1, 2, 3, 4, 5}, 9);
  ASSERT_FALSE(result.path.empty());
  OIIO::ImageBuf sheet{result.path.string()};
  ASSERT_TRUE(sheet.read());
  // Label strip height = clamp(10 / 6, 12, 28) = 12; gap 4.
  // Width 3·(20+4)+4 = 76; height 2·(10+12+4)+4 = 56.
  EXPECT_EQ(sheet.spec().width, 76);
  EXPECT_EQ(sheet.spec().height, 56);
  // Frame 5 is cell index 4: column 1, row 1 → origin (4+24, 4+26) = (28, 30).
  float px[3];
  sheet.getpixel(28 + 10, 30 + 5, px, 3);
  EXPECT_NEAR(px[0], 1.0f, 1.0f / 255);
  EXPECT_NEAR(px[2], 0.0f, 1.0f / 255);
  // Frame 1 at (4, 4): red 0.2.
  sheet.getpixel(4 + 10, 4 + 5, px, 3);
  EXPECT_NEAR(px[0], 0.2f, 1.0f / 255);
}

}  // namespace
}  // namespace raintrace::render
