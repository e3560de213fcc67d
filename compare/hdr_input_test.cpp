// Comparing HDR (scene-linear OpenEXR) input: developed to display values by default, exactly as
// a raintrace PNG says when it meets one, raw with --linear; render folders holding both kinds.
#include "compare/hdr_input.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "compare/compare_run.h"
#include "compare/image_io.h"
#include "compare/report_json.h"
#include "compare/report_table.h"
#include "compare/test_files.h"

namespace raintrace::compare {
namespace {

namespace fs = std::filesystem;
using testing_support::TempDir;

/// A night frame in scene-linear light: a dark facade (0.01–0.05) with a lamp at 300.
Image night(int w = 40, int h = 24) {
  Image img(w, h, 3);
  img.scene_linear = true;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const float facade = 0.01f + 0.04f * float(x) / float(w);
      for (int c = 0; c < 3; ++c) img.at(x, y, c) = facade * (c == 2 ? 0.8f : 1.0f);
    }
  }
  for (int c = 0; c < 3; ++c) img.at(w / 2, h / 2, c) = 300.0f;
  return img;
}

/// Writes a half-float EXR, as POV-Ray's +FE does.
void write_exr(const fs::path& path, const Image& image) {
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out);
  ASSERT_TRUE(out->open(path.string(),
                        OIIO::ImageSpec(image.width, image.height, 3, OIIO::TypeDesc::HALF)));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data()));
  out->close();
}

const film::DisplayTransform& filmic() {
  static const film::DisplayTransform transform;
  return transform;
}

TEST(HdrCompare, ExrIsReadAsSceneLinearAndPngAsDisplayWithItsDescription) {
  TempDir tmp;
  write_exr(tmp.path() / "a.exr", night());
  film::develop_file(tmp.path() / "a.exr", tmp.path() / "a.png", {}, {60, 1, 1}, filmic());
  EXPECT_TRUE(read_image(tmp.path() / "a.exr").scene_linear);
  const Image png = read_image(tmp.path() / "a.png");
  EXPECT_FALSE(png.scene_linear);
  EXPECT_EQ(png.description.rfind("raintrace develop: ", 0), 0U) << png.description;
}

TEST(HdrCompare, AnErrorOnALampIsJudgedAsAViewerSeesItNotByItsLinearSize) {
  // 1 % on a lamp at 300 is 3.0 in linear units, more than every other difference together;
  // on screen the lamp is white either way.
  TempDir tmp;
  Image b = night();
  for (int c = 0; c < 3; ++c) b.at(20, 12, c) = 303.0f;
  write_exr(tmp.path() / "a.exr", night());
  write_exr(tmp.path() / "b.exr", b);
  CompareOptions options;
  options.thresholds.fail = 1.0 / 255.0;
  const auto developed = compare_paths(tmp.path() / "a.exr", tmp.path() / "b.exr", options);
  EXPECT_FALSE(developed.any_failed()) << format_table(developed);
  EXPECT_LT(developed.frames[0].metrics.max_error, 1.0 / 255.0);
  EXPECT_TRUE(developed.frames[0].metrics.display_metrics);
  EXPECT_NE(format_table(developed).find("HDR input developed for comparison: raintrace develop: "
                                         "exposure_ev=0 view=filmic look=medium-high-contrast "
                                         "bloom=0 grain=0 vignette=0"),
            std::string::npos)
      << format_table(developed);

  options.hdr.linear = true;
  const auto linear = compare_paths(tmp.path() / "a.exr", tmp.path() / "b.exr", options);
  EXPECT_TRUE(linear.any_failed());
  EXPECT_NEAR(linear.frames[0].metrics.max_error, 3.0,
              0.25);  // half floats near 300: steps of 0.25
  EXPECT_FALSE(linear.frames[0].metrics.display_metrics);
  const auto json = nlohmann::json::parse(to_json(linear));
  EXPECT_TRUE(json["frames"][0]["psnr"].is_null());
  EXPECT_TRUE(json["frames"][0]["ssim"].is_null());
  EXPECT_TRUE(json["frames"][0]["candidate_developed"].is_null());
  // Relative thresholds are the linear units that make sense: 1 % passes at 2 %.
  options.thresholds.fail_relative = 0.02;
  EXPECT_FALSE(compare_paths(tmp.path() / "a.exr", tmp.path() / "b.exr", options).any_failed());
}

TEST(HdrCompare, AnExrMeetsItsPngDevelopedAsThePngSaysWithinRounding) {
  TempDir tmp;
  write_exr(tmp.path() / "frame_0007.exr", night());
  const film::DevelopSettings settings{.exposure_ev = 1, .bloom = 0.1, .grain = 0.05};
  film::develop_file(tmp.path() / "frame_0007.exr", tmp.path() / "frame_0007.png", settings,
                     {60, 9, 7}, filmic());
  CompareOptions options;
  options.thresholds.fail = 0.5 / 255.0 + 1e-6;  // rounding to 8 bits, nothing more
  const auto report =
      compare_paths(tmp.path() / "frame_0007.png", tmp.path() / "frame_0007.exr", options);
  EXPECT_FALSE(report.any_failed()) << format_table(report);
  EXPECT_EQ(report.frames[0].developed_b,
            film::describe(settings, {.fov_deg = 60, .seed = 9, .frame = 7}));
  EXPECT_TRUE(report.frames[0].developed_a.empty());
  // Developed otherwise (the curve alone), the same EXR is another picture.
  write_image(tmp.path() / "plain.png", read_image(tmp.path() / "frame_0007.png"));
  EXPECT_TRUE(
      compare_paths(tmp.path() / "plain.png", tmp.path() / "frame_0007.exr", options).any_failed());
}

TEST(HdrCompare, LinearValuesDoNotMeetDisplayValues) {
  TempDir tmp;
  write_exr(tmp.path() / "a.exr", night());
  film::develop_file(tmp.path() / "a.exr", tmp.path() / "a.png", {}, {}, filmic());
  CompareOptions options;
  options.hdr.linear = true;
  const auto report = compare_paths(tmp.path() / "a.png", tmp.path() / "a.exr", options);
  ASSERT_EQ(report.frames[0].status, FrameStatus::error);
  EXPECT_NE(report.frames[0].error.find("--linear"), std::string::npos);
}

TEST(HdrCompare, RenderFoldersCompareTheirPngsOrWithPreferHdrTheirExrs) {
  TempDir tmp;
  const fs::path ref = tmp.path() / "reference", out = tmp.path() / "images";
  fs::create_directories(ref);
  fs::create_directories(out);
  for (int n = 1; n <= 2; ++n) {
    const std::string stem = "frame_000" + std::to_string(n);
    write_exr(out / (stem + ".exr"), night());
    film::develop_file(out / (stem + ".exr"), out / (stem + ".png"), {},
                       {.fov_deg = 60, .seed = 1, .frame = n}, filmic());
    fs::copy_file(out / (stem + ".png"), ref / (stem + ".png"));
  }
  const auto pngs = compare_paths(ref, out);
  ASSERT_EQ(pngs.frames.size(), 2U);  // each frame once, not once per file
  EXPECT_EQ(pngs.frames[0].name, "frame_0001.png");
  EXPECT_FALSE(pngs.any_failed()) << format_table(pngs);
  // --hdr: the candidate's EXRs meet the reference PNGs, developed as those say.
  CompareOptions options;
  options.prefer_hdr = true;
  options.thresholds.fail = 0.5 / 255.0 + 1e-6;
  const auto exrs = compare_paths(ref, out, options);
  ASSERT_EQ(exrs.frames.size(), 2U);
  EXPECT_EQ(exrs.frames[1].name, "frame_0002.exr");
  EXPECT_EQ(exrs.frames[1].b.filename(), "frame_0002.exr");
  EXPECT_FALSE(exrs.any_failed()) << format_table(exrs);
}

}  // namespace
}  // namespace raintrace::compare
