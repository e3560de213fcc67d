// Tests for the non-ASCII guard in front of toml++ (scene_ascii.h).
#include "cli/scene_ascii.h"

#include <gtest/gtest.h>

#include "cli/scene.h"

namespace raintrace::cli {
namespace {

TEST(NonAsciiGuard, AllowsNonAsciiInComments) {
  EXPECT_EQ(first_non_ascii_outside_comments("# 640×360, 634 drops/m³\nseed = 1 # ½\n"),
            std::nullopt);
  EXPECT_EQ(first_non_ascii_outside_comments("a = \"#\" # é\n"), std::nullopt);
}

TEST(NonAsciiGuard, FindsNonAsciiInKeysValuesAndStrings) {
  const auto at = [](std::string_view text) {
    const auto where = first_non_ascii_outside_comments(text);
    return where ? std::pair{where->line, where->column} : std::pair{0, 0};
  };
  EXPECT_EQ(at("seed = 1\nfram\xc2\xb3 = 2\n"), std::pair(2, 5));
  EXPECT_EQ(at("\xcc\xaa"), std::pair(1, 1));  // marzer/tomlplusplus#295's input
  // A '#' inside a string does not start a comment.
  EXPECT_EQ(at("a = \"# not a comment \xc3\xa9\"\n"), std::pair(1, 22));
  EXPECT_EQ(at("a = '#' \xc3\xa9\n"), std::pair(1, 9));
  // An escaped quote does not end a basic string.
  EXPECT_EQ(at("a = \"\\\" # \xc3\xa9\"\n"), std::pair(1, 11));
  // marzer/tomlplusplus#190's input: inside a multi-line string after a line-ending backslash.
  EXPECT_EQ(at("s = \"\"\"\\\n\xc2\xa7\"\"\"\n"), std::pair(2, 1));
  EXPECT_EQ(at("s = '''\n# \n\xc2\xa7'''\n"), std::pair(3, 1));
  // Extra closing quotes belong to a multi-line string; the '#' after them is a comment.
  EXPECT_EQ(at("s = \"\"\"a\"\"\"\"\" # \xc3\xa9\n"), std::pair(0, 0));
}

TEST(NonAsciiGuard, LoaderReportsItAsASyntaxErrorAtItsPlace) {
  try {
    load_scene_string("seed = 1\n[output]\nfram\xc2\xb3 = 2\n", "t.toml", ".");
    FAIL() << "expected SceneError";
  } catch (const SceneError& e) {
    EXPECT_STREQ(e.what(),
                 "t.toml:3:5: syntax error: non-ASCII character outside a comment (keys and "
                 "values are plain ASCII)");
  }
}

}  // namespace
}  // namespace raintrace::cli
