// Tests that every example scene and the complete example in docs/scene-format.md load, and
// that the examples show what their comment headers say (the paper's figures).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <sstream>

#include "cli/scene.h"
#include "cli/scene_format_doc.h"

namespace raintrace::cli {
namespace {

namespace fs = std::filesystem;

const fs::path kSourceDir = RAINTRACE_SOURCE_DIR;

Scene example(const std::string& name) {
  return load_scene_file(kSourceDir / "examples" / (name + ".toml"));
}

TEST(Examples, EveryExampleLoads) {
  int loaded = 0;
  for (const auto& entry : fs::directory_iterator(kSourceDir / "examples")) {
    if (entry.path().extension() != ".toml") continue;
    EXPECT_NO_THROW(load_scene_file(entry.path())) << entry.path();
    ++loaded;
  }
  EXPECT_GE(loaded, 10);
}

TEST(Examples, EachStartsWithACommentHeaderNamingItself) {
  for (const auto& entry : fs::directory_iterator(kSourceDir / "examples")) {
    if (entry.path().extension() != ".toml") continue;
    std::ifstream in(entry.path());
    std::string first_line;
    std::getline(in, first_line);
    EXPECT_EQ(first_line.rfind("# " + entry.path().filename().string() + " — ", 0), 0u)
        << entry.path();
  }
}

TEST(Examples, DefaultIsAShortNightStreetInModerateRain) {
  const Scene scene = example("default");
  EXPECT_EQ(scene.look.environment.name, "night_street");
  EXPECT_EQ(scene.look.quality, povgen::Quality::preview);
  EXPECT_LE(scene.frames / scene.look.fps, 4.0);  // a few seconds of clip
  EXPECT_LE(scene.look.width * scene.look.height, 640 * 360);
  EXPECT_GE(scene.sim.rain.rate_mm_per_h, 2.0);  // "moderate": 2.5–10 mm/h in the usual scale
  EXPECT_LE(scene.sim.rain.rate_mm_per_h, 10.0);
}

TEST(Examples, LightRainIsLighterThanDefaultWhichIsLighterThanHeavyRain) {
  EXPECT_LT(example("light_rain").sim.rain.rate_mm_per_h,
            example("default").sim.rain.rate_mm_per_h);
  EXPECT_LT(example("default").sim.rain.rate_mm_per_h,
            example("heavy_rain").sim.rain.rate_mm_per_h);
}

TEST(Examples, ThunderstormStrikesWithinItsClip) {
  const Scene scene = example("thunderstorm");
  EXPECT_TRUE(scene.sim.lightning.enabled);
  const double clip_s = (scene.frames - 1) / scene.look.fps;
  EXPECT_GE(scene.sim.lightning.first_strike_s, 0.0);
  // The whole flash fits in the clip, so every return stroke is seen.
  EXPECT_LE(scene.sim.lightning.first_strike_s + scene.sim.lightning.flash_duration_s, clip_s);
}

TEST(Examples, FogSeriesChangesOnlyTheFog) {
  const Scene none = example("no_fog");
  const Scene little = example("little_fog");
  const Scene heavy = example("heavy_fog");
  EXPECT_EQ(none.look.fog.mode, povgen::FogMode::off);
  EXPECT_EQ(little.look.fog.mode, povgen::FogMode::media);
  EXPECT_EQ(heavy.look.fog.mode, povgen::FogMode::media);
  EXPECT_LT(little.look.fog.density_per_m, heavy.look.fog.density_per_m);
  for (const Scene* scene : {&little, &heavy}) {
    EXPECT_EQ(scene->sim.seed, none.sim.seed);
    EXPECT_EQ(scene->frames, none.frames);
    EXPECT_EQ(scene->sim.camera.position, none.sim.camera.position);
    EXPECT_EQ(scene->sim.camera.look_at, none.sim.camera.look_at);
    EXPECT_EQ(scene->sim.rain.rate_mm_per_h, none.sim.rain.rate_mm_per_h);
    EXPECT_EQ(scene->sim.rain.far_m, none.sim.rain.far_m);
  }
}

TEST(Examples, StreaksUseALongExposure) {
  EXPECT_GE(example("streaks").sim.camera.exposure_s, 4 * sim::Camera{}.exposure_s);
}

TEST(Examples, CloseupIsAMacroShotOfTheDropWithTheRestOutOfFocus) {
  const Scene scene = example("closeup");
  EXPECT_EQ(scene.look.environment.name, "closeup");
  // closeup.inc's big drop sits at the origin; the lens focuses on it from a few centimetres.
  EXPECT_LT(glm::length(scene.sim.camera.look_at), 0.003);
  EXPECT_LT(glm::length(scene.sim.camera.position - scene.sim.camera.look_at), 0.05);
  // An open aperture: everything but the drop is blurred.
  EXPECT_GT(scene.look.aperture_m, 0.0);
  // The falling rain lies behind the drop, out of focus.
  EXPECT_GT(scene.sim.rain.near_m, 0.1);
}

/// The ```toml block that follows `marker` in the file.
std::string toml_block_after(const fs::path& file, const std::string& marker) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const std::size_t at = doc.find(marker);
  if (at == std::string::npos) return {};
  const std::size_t start = doc.find("```toml\n", at);
  const std::size_t end = doc.find("\n```", start);
  if (start == std::string::npos || end == std::string::npos) return {};
  return doc.substr(start + 8, end - start - 7);
}

TEST(SceneFormatDoc, CompleteExampleLoadsAndSetsEveryKey) {
  const fs::path doc = kSourceDir / "docs" / "scene-format.md";
  const std::string block = toml_block_after(doc, "<!-- complete example -->");
  ASSERT_FALSE(block.empty()) << "no complete example block in " << doc;
  EXPECT_NO_THROW(load_scene_string(block, "scene-format.md", kSourceDir / "docs"));
  // Every key of the format appears in the example, so the example documents them all
  // (environment.include only as a comment: it needs a file beside the scene).
  for (const SceneFormatRow& row : scene_format_rows()) {
    std::size_t from = 0;
    if (!row.section.empty()) {
      from = block.find("[" + row.section + "]");
      ASSERT_NE(from, std::string::npos) << "[" << row.section << "] missing";
    }
    const std::size_t to = block.find("\n[", from + 1);
    const std::string part = block.substr(from, to == std::string::npos ? to : to - from);
    const std::string prefix = row.section == "environment" && row.key == "include" ? "# " : "";
    EXPECT_NE(part.find("\n" + prefix + row.key + " = "), std::string::npos)
        << row.section << "." << row.key << " missing from the complete example";
  }
}

TEST(SceneFormatDoc, ErrorExamplesAreTheLoadersOwnWords) {
  // Each row of the doc's error table reads: | `LINE` under `[SECTION]` … | `MESSAGE` |. The row
  // is replayed as a file whose line 3 is the section header and line 4 the line, named
  // rain.toml like the doc says; a message ending in "…" is compared up to there.
  std::ifstream in(kSourceDir / "docs" / "scene-format.md");
  std::string row;
  int replayed = 0;
  while (std::getline(in, row)) {
    if (row.rfind("| `", 0) != 0 || row.find("rain.toml:4:") == std::string::npos) continue;
    const std::size_t line_end = row.find('`', 3);
    const std::string line = row.substr(3, line_end - 3);
    std::string section = "[rain]";
    if (const std::size_t under = row.find("under `[", line_end); under != std::string::npos) {
      section = row.substr(under + 7, row.find('`', under + 7) - under - 7);
    }
    const std::size_t message_start = row.find("`rain.toml:4:") + 1;
    std::string message = row.substr(message_start, row.find('`', message_start) - message_start);
    if (const std::size_t ellipsis = message.find("…"); ellipsis != std::string::npos) {
      message.resize(ellipsis);
    }
    const std::string text =
        "# replayed from docs/scene-format.md\n\n" + section + "\n" + line + "\n";
    std::string actual;
    try {
      load_scene_string(text, "rain.toml", kSourceDir / "docs");
    } catch (const SceneError& e) {
      actual = e.what();
    }
    EXPECT_EQ(actual.substr(0, message.size()), message) << "row: " << row;
    ++replayed;
  }
  EXPECT_GE(replayed, 8);
}

}  // namespace
}  // namespace raintrace::cli
