// Values → POV-Ray text: golden text for tiny hand-built frames, determinism across thread
// counts, and refusal of non-finite numbers.
#include "povgen/frame_text.h"

#include <gtest/gtest.h>
#include <limits>
#include <stdexcept>

#include "povgen/frame_values.h"
#include "povgen/test_support/synthetic_rain.h"

namespace raintrace::povgen {
namespace {

/// One motion and one opacity level: two cells (resolved, sub-pixel) of 16×64 texels side by
/// side. Cell 0's uv quad, inset by half a texel: u 0.5/32 … 15.5/32, v 0.5/64 … 63.5/64.
StreakAtlasLayout one_cell() { return StreakAtlasLayout{1, 1, 16, 64}; }

TEST(FrameText, GoldenTinyFrame) {
  FrameValues values;
  values.index = 7;
  values.time_s = 0.625;
  values.flash = 0.5f;
  values.flash_position = {1.0f, 300.0f, 200.0f};
  values.drops.push_back({{0.5f, 1.25f, -2.0f}, 0.001f, 1.0f});
  values.drops.push_back({{0.0f, 2.0f, -1.5f}, 0.0025f, 0.75f});
  StreakValue streak;
  streak.corners = {glm::vec3{0.0f, 2.0f, 4.0f}, glm::vec3{0.5f, 2.0f, 4.0f},
                    glm::vec3{0.5f, 1.0f, 4.0f}, glm::vec3{0.0f, 1.0f, 4.0f}};
  streak.cell = 0;
  values.streaks.push_back(streak);
  values.bolts.push_back({{{{0.0f, 100.0f, 50.0f}, {2.0f, 0.0f, 50.0f}, 0.5f, 1.0f}}, 0.25f});
  const std::string expected =
      "// raintrace frame 7\n"
      "#version 3.7;\n"
      "#declare RT_Flash=0.5;\n"
      "#declare RT_FlashPosition=<1,300,200>;\n"
      "#declare RT_Time=0.625;\n"
      "#declare RT_Bolts=1;\n"
      "#include \"scene.inc\"\n"
      "union{\n"
      "sphere{<0.5,1.25,-2>,0.001}\n"
      "sphere{0,0.0025 scale<1,0.75,1>translate<0,2,-1.5>}\n"
      "material{RT_DropMaterial}\n"
      "no_shadow hollow\n"
      "}\n"
      "mesh2{\n"
      "vertex_vectors{4,\n"
      "<0,2,4>,<0.5,2,4>,<0.5,1,4>,<0,1,4>,\n"
      "}\n"
      "uv_vectors{4,\n"
      "<0.015625,0.9921875>,<0.484375,0.9921875>,<0.484375,0.0078125>,<0.015625,0.0078125>,\n"
      "}\n"
      "face_indices{2,\n"
      "<0,1,2>,<0,2,3>,\n"
      "}\n"
      "uv_indices{2,\n"
      "<0,1,2>,<0,2,3>,\n"
      "}\n"
      "texture{RT_StreakTexture}\n"
      "no_shadow no_reflection hollow\n"
      "}\n"
      "#if(RT_Mask=0)\n"
      "union{\n"
      "cylinder{<0,100,50>,<2,0,50>,1 RT_BoltCore(0.125)}\n"
      "no_shadow hollow\n"
      "#if(RT_BoltBlur>0) no_reflection #end\n"
      "}\n"
      "#if(RT_BoltBlur>0)\n"
      "union{\n"
      "RT_BoltMirrored(<0,100,50>,<2,0,50>,1,0.125)\n"
      "no_shadow hollow no_image no_radiosity\n"
      "}\n"
      "#end\n"
      "merge{\n"
      "cylinder{<0,100,50>,<2,0,50>,4}\n"
      "sphere{<0,100,50>,4.004}\n"
      "sphere{<2,0,50>,4.004}\n"
      "RT_BoltGlow(0.25)\n"
      "no_shadow hollow\n"
      "}\n"
      "#end\n";
  EXPECT_EQ(frame_text(values, one_cell()), expected);
}

TEST(FrameText, EmptyFrameHasOnlyTheHeader) {
  FrameValues values;
  values.index = 1;
  EXPECT_EQ(frame_text(values),
            "// raintrace frame 1\n#version 3.7;\n#declare RT_Flash=0;\n"
            "#declare RT_FlashPosition=<0,0,0>;\n#declare RT_Time=0;\n#include \"scene.inc\"\n");
}

TEST(FrameText, FrameWithABoltSaysSoBeforeTheSceneInclude) {
  // scene.inc reads RT_Bolts to trace the full environment (not the plate) behind a bolt.
  FrameValues values;
  values.index = 2;
  BoltValue bolt;
  bolt.brightness = 1.0;
  bolt.segments.push_back({{0, 100, 200}, {5, 0, 200}, 0.5, 0.5});
  values.bolts.push_back(bolt);
  const std::string text = frame_text(values);
  const auto bolts = text.find("#declare RT_Bolts=1;\n");
  ASSERT_NE(bolts, std::string::npos);
  EXPECT_LT(bolts, text.find("#include \"scene.inc\""));
  values.bolts.front().segments.clear();  // an empty bolt draws nothing
  EXPECT_EQ(frame_text(values).find("RT_Bolts"), std::string::npos);
}

TEST(FrameText, ABoltDrawnHalfAsThickShinesTwiceAsBrightPerSurface) {
  // RT_BoltCore's and RT_BoltGlow's emission is per unit of surface, set for a 0.6 m trunk: a
  // channel drawn half as thick keeps its light per metre by emitting twice as much.
  FrameValues values;
  BoltValue bolt;
  bolt.brightness = 0.5f;
  bolt.segments.push_back({{0, 100, 200}, {5, 0, 200}, 0.3f, 0.3f});
  bolt.trunk_radius = 0.3f;
  values.bolts.push_back(bolt);
  std::string text = frame_text(values);
  EXPECT_NE(text.find("RT_BoltCore(1)"), std::string::npos) << text;
  EXPECT_NE(text.find("RT_BoltGlow(1)"), std::string::npos) << text;
  values.bolts.front().trunk_radius = kBoltLightTrunkRadius_m;  // the radius it is set for
  text = frame_text(values);
  EXPECT_NE(text.find("RT_BoltCore(0.5)"), std::string::npos) << text;
  EXPECT_NE(text.find("RT_BoltGlow(0.5)"), std::string::npos) << text;
}

TEST(FrameText, OnlyUsedCellsGetUvQuadsInCellOrder) {
  // Cells 5 and 0 of the default atlas: uv_vectors only for those two, cell 0 first (uv
  // indices 0..3), cell 5 second (4..7).
  FrameValues values;
  StreakValue s;
  s.corners = {glm::vec3{0.0f}, glm::vec3{1.0f, 0.0f, 0.0f}, glm::vec3{1.0f, 1.0f, 0.0f},
               glm::vec3{0.0f, 1.0f, 0.0f}};
  s.cell = 5;
  values.streaks.push_back(s);
  s.cell = 0;
  values.streaks.push_back(s);
  const std::string text = frame_text(values);
  EXPECT_NE(text.find("face_indices{4,\n<0,1,2>,<0,2,3>,\n<4,5,6>,<4,6,7>,\n}"), std::string::npos);
  EXPECT_NE(text.find("uv_indices{4,\n<4,5,6>,<4,6,7>,\n<0,1,2>,<0,2,3>,\n}"), std::string::npos);
  EXPECT_NE(text.find("uv_vectors{8,"), std::string::npos);
  // Cell 5 is column 5 of row 0: u from (5·8 + 0.5)/128 = 0.31640625, written to 7 digits.
  EXPECT_NE(text.find("<0.3164063,"), std::string::npos);
}

TEST(FrameText, FaceAndUvIndicesCountUpAcrossDigitCarries) {
  // 3000 quads: vertex indices up to 11999, through every digit count and every carry
  // (4i + 2 rolls over when 4i ends in 8); cells cycle through the first 64 of the atlas, all
  // used, so each keeps its own place.
  FrameValues values;
  std::string faces = "face_indices{6000,\n";
  std::string uvs = "uv_indices{6000,\n";
  auto pair = [](std::size_t v) {
    const auto n = [](std::size_t x) { return std::to_string(x); };
    return "<" + n(v) + "," + n(v + 1) + "," + n(v + 2) + ">,<" + n(v) + "," + n(v + 2) + "," +
           n(v + 3) + ">,\n";
  };
  for (std::size_t i = 0; i < 3000; ++i) {
    StreakValue s;
    s.corners = {glm::vec3{0.0f}, glm::vec3{1.0f}, glm::vec3{2.0f}, glm::vec3{3.0f}};
    s.cell = static_cast<int>(i * 7 % 64);
    values.streaks.push_back(s);
    faces += pair(4 * i);
    uvs += pair(4 * static_cast<std::size_t>(s.cell));
  }
  const std::string text = frame_text(values);
  EXPECT_NE(text.find(faces + "}\n"), std::string::npos);
  EXPECT_NE(text.find(uvs + "}\n"), std::string::npos);
}

TEST(FrameText, StreakCellOutsideTheAtlasIsRefused) {
  FrameValues values;
  StreakValue s;
  s.corners = {glm::vec3{0.0f}, glm::vec3{1.0f}, glm::vec3{2.0f}, glm::vec3{3.0f}};
  s.cell = 2;
  values.streaks.push_back(s);
  EXPECT_THROW(frame_text(values, one_cell()), std::invalid_argument);
}

TEST(FrameText, SameFrameGivesIdenticalBytesWhateverTheThreadCount) {
  ExportParams look;
  look.min_streak_coverage = 0.0;  // every drop a streak: several chunks
  const sim::Frame frame =
      test_support::synthetic_rain(60000, look.camera, 16.0 / 9.0, 12.0, 2.0, 3);
  const FrameValues values = build_frame_values(frame, look);
  ASSERT_GT(values.streaks.size(), 40000u);  // several chunks of 16384
  const std::string one = frame_text(values, {}, 1);
  EXPECT_EQ(one, frame_text(values, {}, 1));
  EXPECT_EQ(one, frame_text(values, {}, 2));
  EXPECT_EQ(one, frame_text(values, {}, 3));
}

TEST(FrameText, NonFiniteValuesAreRefused) {
  FrameValues values;
  values.drops.push_back({{std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.0f}, 0.001f, 1.0f});
  EXPECT_THROW(frame_text(values), std::invalid_argument);
  EXPECT_THROW(frame_text(values, {}, 2), std::invalid_argument);
  FrameValues streak;
  streak.streaks.push_back({{glm::vec3{0.0f}, glm::vec3{std::numeric_limits<float>::infinity()},
                             glm::vec3{1.0f}, glm::vec3{1.0f}},
                            0});
  EXPECT_THROW(frame_text(streak), std::invalid_argument);
  FrameValues flash;
  flash.flash = std::numeric_limits<float>::infinity();
  EXPECT_THROW(frame_text(flash), std::invalid_argument);
}

TEST(FrameText, MaskReusesTheFrameFile) {
  EXPECT_EQ(mask_text("frames/frame_0003.pov"),
            "// raintrace rain mask: the frame's rain in white on black\n#version 3.7;\n"
            "#declare RT_Mask=1;\n#include \"frames/frame_0003.pov\"\n");
  EXPECT_THROW(mask_text("frames/x\"\n#system"), std::invalid_argument);
  EXPECT_THROW(mask_text("../etc/passwd"), std::invalid_argument);
  EXPECT_THROW(mask_text("/etc/passwd"), std::invalid_argument);
}

TEST(FrameText, FrameNamesHaveFourDigitsOrMore) {
  EXPECT_EQ(frame_digits(48), 4);
  EXPECT_EQ(frame_digits(9999), 4);
  EXPECT_EQ(frame_digits(10000), 5);
  EXPECT_EQ(frame_file_name("frame", 1, 4, ".pov"), "frame_0001.pov");
  EXPECT_EQ(frame_file_name("mask", 48, 4, ".png"), "mask_0048.png");
  EXPECT_EQ(frame_file_name("frame", 12345, 5, ".pov"), "frame_12345.pov");
}

}  // namespace
}  // namespace raintrace::povgen
