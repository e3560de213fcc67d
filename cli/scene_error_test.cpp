// Tests for the wording of scene-file errors: one line, escaped user text.
#include "cli/scene_error.h"

#include <gtest/gtest.h>

namespace raintrace::cli {
namespace {

TEST(SceneErrorText, HasFileLineColumnKeyAndMessage) {
  EXPECT_EQ(
      scene_error_text("rain.toml", {4, 17}, "rain.rate_mm_per_h", "must be in [0, 500], got -3"),
      "rain.toml:4:17: rain.rate_mm_per_h: must be in [0, 500], got -3");
}

TEST(SceneErrorText, DropsUnknownLocationAndEmptyKey) {
  EXPECT_EQ(scene_error_text("a.toml", {}, "", "cannot read"), "a.toml: cannot read");
}

TEST(SceneErrorText, StaysOnOneLineWhateverTheInput) {
  const std::string text = scene_error_text("a\nb.toml", {1, 2}, "k\ney", "two\nlines\r");
  EXPECT_EQ(text.find('\n'), std::string::npos);
  EXPECT_EQ(text.find('\r'), std::string::npos);
  EXPECT_EQ(text, "a\\nb.toml:1:2: k\\ney: two lines ");
}

TEST(SceneErrorText, AHugeKeyOrFileNameIsCutNotEchoedWhole) {
  // A 15 MB unknown key used to come back whole in the error line.
  const std::string key(15'000'000, 'x');
  const std::string text = scene_error_text("a.toml", {2, 1}, "rain." + key, "unknown key");
  EXPECT_LT(text.size(), 200U);
  EXPECT_EQ(text, "a.toml:2:1: rain." + std::string(75, 'x') + "…: unknown key");
  EXPECT_LT(scene_error_text(std::string(100000, 'f'), {}, "", "cannot read").size(), 300U);
}

TEST(Escaped, WritesControlAndNonAsciiBytesAsEscapes) {
  // ESC (0x1b) would start a terminal control sequence; é is two UTF-8 bytes c3 a9.
  EXPECT_EQ(escaped("a\x1b[31mb\t\\\xc3\xa9"), "a\\x1b[31mb\\t\\\\\\xc3\\xa9");
}

TEST(InQuotes, EscapesQuotesAndCutsLongText) {
  EXPECT_EQ(in_quotes("say \"hi\""), "\"say \\\"hi\\\"\"");
  EXPECT_EQ(in_quotes("abcdef", 3), "\"abc\"…");
}

}  // namespace
}  // namespace raintrace::cli
