// POV-Ray command lines, file names and error-line extraction.
#include "render/povray_command.h"

#include <gtest/gtest.h>

namespace raintrace::render {
namespace {

TEST(PovArgv, RendersASpanOfTheWholeAnimationHeadlessIntoTheTempFolder) {
  const auto argv = povray_argv(Pass::image, {9, 16});
  const std::vector<std::string> expected{
      "povray", "scene.ini", "-D",   "+FE",  "+V", "+RS7", "-GR", "+L.", "+Oimages/.tmp/frame_.exr",
      "+KFI1",  "+KFF9999",  "+SF9", "+EF16"};
  EXPECT_EQ(argv, expected);
}

TEST(PovArgv, MaskPassUsesMaskIniAndMaskNames) {
  const auto argv = povray_argv(Pass::mask, {1, 1});
  EXPECT_EQ(argv[1], "mask.ini");
  EXPECT_EQ(argv[3], "+FN");  // a mask is data, not light: PNG
  EXPECT_NE(std::find(argv.begin(), argv.end(), "+Oimages/.tmp/mask_.png"), argv.end());
}

TEST(PovArgv, FinalFrameHasAsManyNinesAsTheFileNamesHaveDigits) {
  // 12 000 frames → 5-digit names; Final_Frame 99999 makes POV-Ray pad to 5 as well.
  const auto argv = povray_argv(Pass::image, {10000, 10010}, 5);
  EXPECT_NE(std::find(argv.begin(), argv.end(), "+KFF99999"), argv.end());
  EXPECT_EQ(final_image_name(Pass::image, 10000, 5), "images/frame_10000.exr");
  EXPECT_EQ(developed_image_name(10000, 5), "images/frame_10000.png");
  EXPECT_EQ(temp_image_name(Pass::image, 7, 5), "images/.tmp/frame_00007.exr");
  EXPECT_EQ(temp_developed_name(7, 5), "images/.tmp/frame_00007.png");
}

TEST(PovArgv, EnvironmentPlateIsOneStillFromPlateIniIntoTheTempFolder) {
  const std::vector<std::string> expected{
      "povray", "plate.ini", "-D",  "+FE",
      "-V",     "-GR",       "+L.", "+Oimages/.tmp/environment_plate.exr"};
  EXPECT_EQ(environment_plate_argv(), expected);
  EXPECT_EQ(environment_plate_temp_name(), "images/.tmp/environment_plate.exr");
}

TEST(ImageNames, AreFourDigitLikeScenesFinalFrame9999) {
  EXPECT_EQ(final_image_name(Pass::image, 7), "images/frame_0007.exr");
  EXPECT_EQ(developed_image_name(7), "images/frame_0007.png");
  EXPECT_EQ(temp_image_name(Pass::image, 12), "images/.tmp/frame_0012.exr");
  EXPECT_EQ(final_image_name(Pass::mask, 123), "images/mask_0123.png");
}

// Verbatim tail of a POV-Ray 3.7.0.10 log (-V -GR) whose frame 3 had a bad token.
constexpr const char* kParseErrorLog =
    "  Trace Time:       0 hours  0 minutes  0 seconds (0.002 seconds)\n"
    "Possible Parse Error: assumed_gamma not specified in this POV-Ray 3.7 or later\n"
    " scene. Future versions of POV-Ray may consider this a fatal error.\n"
    "Rendering frame 2 of 3\n"
    "==== [Parsing...] ==========================================================\n"
    "\n"
    "File 'frames/frame_0003.pov' line 4: Parse Error: Expected 'numeric expression',\n"
    " undeclared identifier 'oops' found instead\n"
    "Fatal error in parser: Cannot parse input.\n"
    "Render failed\n";

TEST(PovErrorLines, JoinsTheWrappedLocationLineAndKeepsTheVerdict) {
  const auto lines = povray_error_lines(kParseErrorLog);
  ASSERT_EQ(lines.size(), 3U);
  EXPECT_EQ(lines[0],
            "File 'frames/frame_0003.pov' line 4: Parse Error: Expected 'numeric expression', "
            "undeclared identifier 'oops' found instead");
  EXPECT_EQ(lines[1], "Fatal error in parser: Cannot parse input.");
  EXPECT_EQ(lines[2], "Render failed");
}

// Tail of a POV-Ray 3.7.0.10 log whose scene asks for a font it cannot find, as it printed it
// (file name and line changed to the street's include): the error that names the font is only a
// "Possible Parse Error", the fatal one names no file.
constexpr const char* kMissingFontLog =
    "==== [Parsing...] ==========================================================\n"
    "File 'environment.inc' line 470: Possible Parse Error: Cannot find file\n"
    " 'cyrvetic.ttf', even after trying to append file type extension.\n"
    "File 'environment.inc' line 470: Possible Parse Error: Cannot open font file.\n"
    "Fatal error in parser: Cannot open file.\n"
    "Render failed\n";

TEST(PovErrorLines, AMissingFontNamesThePackageThatShipsIt) {
  const auto lines = povray_error_lines(kMissingFontLog);
  ASSERT_EQ(lines.size(), 3U);
  EXPECT_NE(lines[0].find("line 470"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("install the Debian package povray-includes"), std::string::npos)
      << lines[0];
  EXPECT_EQ(lines[1], "Fatal error in parser: Cannot open file.");
}

TEST(PovErrorLines, StatisticsAloneAreNoError) {
  EXPECT_TRUE(
      povray_error_lines("  Parse Time: 0 hours\n  Trace Time: 1 s\nPOV-Ray finished\n").empty());
}

// A POV-Ray 3.7.0.10 log with +V, as it printed it (a 64×64 scene, frames 1–3, frame 2 with a
// bad token): each block's "Rendered N of M pixels" ends with a carriage return, the last
// before the frame's statistics with a newline as well.
constexpr const char* kProgressLog =
    "==== [Rendering...] ========================================================\n"
    "Rendered 1024 of 4096 pixels (25%)\rRendered 2048 of 4096 pixels (50%)\rRendered 3072 of "
    "4096 pixels (75%)\rRendered 4096 of 4096 pixels (100%)\r\n"
    "----------------------------------------------------------------------------\n"
    "Render Statistics\n"
    "  Trace Time:       0 hours  0 minutes  0 seconds (0.002 seconds)\n"
    "\n"
    "Rendering frame 2 of 3\n"
    "==== [Parsing...] ==========================================================\n"
    "\n"
    "File 's.pov' line 5: Parse Error: Expected 'object or directive', undeclared\n"
    " identifier 'oops' found instead\n"
    "Fatal error in parser: Cannot parse input.\n"
    "Render failed\n";

TEST(PovErrorLines, ProgressBeforeTheErrorIsNoPartOfIt) {
  const auto lines = povray_error_lines(kProgressLog);
  ASSERT_EQ(lines.size(), 3U);
  EXPECT_EQ(lines[0],
            "File 's.pov' line 5: Parse Error: Expected 'object or directive', undeclared "
            "identifier 'oops' found instead");
  // A message printed on the progress's line keeps only what follows its last carriage return.
  const auto mid_frame =
      povray_error_lines("Rendered 1024 of 4096 pixels (25%)\rFatal error in render: x.\n");
  ASSERT_EQ(mid_frame.size(), 1U);
  EXPECT_EQ(mid_frame[0], "Fatal error in render: x.");
}

TEST(PovTracedShare, IsTheLastProgressLinesShare) {
  EXPECT_DOUBLE_EQ(*povray_traced_share("Rendered 1024 of 4096 pixels (25%)\rRendered 3072 of "
                                        "4096 pixels (75%)\r"),
                   0.75);
  // A tail that cut the first line short still has a whole last one.
  EXPECT_DOUBLE_EQ(*povray_traced_share("4096 pixels (50%)\rRendered 2048 of 4096 pix"), 0.5);
  EXPECT_DOUBLE_EQ(*povray_traced_share(kProgressLog), 1.0);  // frame 1 whole, then the error
  EXPECT_FALSE(povray_traced_share("==== [Parsing...] ====\n").has_value());
  EXPECT_FALSE(povray_traced_share("Rendered 12").has_value());  // cut mid-number: no share
  EXPECT_FALSE(povray_traced_share("Rendered 9 of 4 pixels").has_value());
}

// The whole log of a POV-Ray 3.7.0.10 that gave up at its start, from a CI run with two test
// processes tracing beside it: it exited with code 1 and wrote no image.
TEST(PovStartup, TheWorkerThreadsTimeoutIsADidNotStartAndAParseErrorIsNot) {
  EXPECT_TRUE(povray_did_not_start("Timed out waiting for worker thread startup\n"));
  EXPECT_FALSE(povray_did_not_start(kParseErrorLog));
  EXPECT_FALSE(povray_did_not_start("  Trace Time: 1 s\nPOV-Ray finished\n"));
}

}  // namespace
}  // namespace raintrace::render
