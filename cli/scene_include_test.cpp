// Tests that [environment] include lets through only a plain .inc inside the scene's folder:
// anything else could make POV-Ray (which enforces no file restrictions) read or write files.
#include "cli/scene_include.h"

#include <gtest/gtest.h>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/scene.h"
#include "cli/scene_error.h"

namespace raintrace::cli {
namespace {

namespace fs = std::filesystem;

class IncludePath : public testing::Test {
 protected:
  void SetUp() override {
    // ctest runs tests in parallel processes: one folder per test.
    m_root = fs::path(testing::TempDir()) /
             ("raintrace_include_test_" +
              std::string{testing::UnitTest::GetInstance()->current_test_info()->name()});
    fs::remove_all(m_root);
    fs::create_directories(m_root / "scenes" / "env");
    std::ofstream(m_root / "scenes" / "env" / "street.inc") << "// ok\n";
    std::ofstream(m_root / "scenes" / "top.inc") << "// ok\n";
    std::ofstream(m_root / "secret.inc") << "// outside the scene folder\n";
    fs::create_symlink(m_root / "secret.inc", m_root / "scenes" / "link.inc");
  }
  void TearDown() override { fs::remove_all(m_root); }

  [[nodiscard]] fs::path scenes() const { return m_root / "scenes"; }

  /// The message of rejecting `text`, or "" when it is accepted.
  [[nodiscard]] std::string rejection(const std::string& text) const {
    try {
      validate_include_path(text, scenes());
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  }

  fs::path m_root;
};

TEST_F(IncludePath, AcceptsARelativeIncludeInsideTheFolder) {
  EXPECT_EQ(validate_include_path("env/street.inc", scenes()), fs::path("env/street.inc"));
  EXPECT_EQ(validate_include_path("./top.inc", scenes()), fs::path("top.inc"));
  // ".." that stays inside the folder is harmless and normalised away.
  EXPECT_EQ(validate_include_path("env/../top.inc", scenes()), fs::path("top.inc"));
}

TEST_F(IncludePath, RejectsHostilePathsWithTheRuleTheyBreak) {
  EXPECT_NE(rejection("../../etc/passwd").find("must name a POV-Ray include ending in \".inc\""),
            std::string::npos);
  EXPECT_NE(rejection("../secret.inc").find("must stay inside the scene file's folder"),
            std::string::npos);
  EXPECT_NE(rejection("env/../../secret.inc").find("must stay inside the scene file's folder"),
            std::string::npos);
  EXPECT_NE(rejection("/etc/povray/3.7/povray.inc").find("got absolute path"), std::string::npos);
  EXPECT_NE(rejection("link.inc").find("symbolic link"), std::string::npos);
  EXPECT_NE(rejection("missing.inc").find("no such file"), std::string::npos);
  EXPECT_NE(rejection("env").find("ending in \".inc\""), std::string::npos);
  EXPECT_NE(rejection("").find("must not be empty"), std::string::npos);
  EXPECT_NE(rejection(std::string(300, 'a') + ".inc").find("at most 255"), std::string::npos);
}

TEST_F(IncludePath, RejectsEveryCharacterThatCouldEscapeAPovRayString) {
  // A quote ends POV-Ray's string; '#' starts a directive such as #fopen or #system-like
  // tricks; a newline starts a new statement; a backslash escapes; spaces and ';' are not
  // needed in file names. Each must be refused before any file-system check.
  for (const std::string& text : std::vector<std::string>{
           "a\".inc", "#fopen.inc", "top.inc\n#fopen F \"/etc/passwd\" read", "a\\b.inc", "a b.inc",
           "a;b.inc", "$HOME.inc", "a'b.inc", "\xc3\xa9.inc", std::string("a\0b.inc", 7)}) {
    const std::string message = rejection(text);
    EXPECT_NE(message.find("must use only the characters"), std::string::npos)
        << in_quotes(text) << " gave: " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST_F(IncludePath, SceneLoaderReportsTheRuleAtTheValue) {
  try {
    load_scene_string("[environment]\ninclude = \"../../etc/passwd\"\n", "t.toml", scenes());
    FAIL() << "expected SceneError";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              "t.toml:2:11: environment.include: must name a POV-Ray include ending in \".inc\", "
              "got \"../../etc/passwd\"");
  }
  try {
    load_scene_string("[environment]\ninclude = \"a\\n#fopen.inc\"\n", "t.toml", scenes());
    FAIL() << "expected SceneError";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("t.toml:2:11: environment.include: must use only", 0), 0u)
        << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
}

TEST_F(IncludePath, SceneLoaderStoresTheNormalisedPath) {
  const Scene scene =
      load_scene_string("[environment]\ninclude = \"env/./street.inc\"\n", "t.toml", scenes());
  EXPECT_EQ(scene.look.environment.include_path, "env/street.inc");
  EXPECT_EQ(scene.base_dir, scenes());
}

}  // namespace
}  // namespace raintrace::cli
