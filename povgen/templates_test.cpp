// Built-in templates and the user include checks: hostile names and paths are rejected.
#include "povgen/templates.h"

#include <gtest/gtest.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "povgen/output_folder.h"
#include "tests/support/command.h"

namespace raintrace::povgen {
namespace {

namespace fs = std::filesystem;

class UserInclude : public ::testing::Test {
 protected:
  void SetUp() override {
    // ctest runs each test in its own process, in parallel: one folder per test and process.
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    m_root = raintrace::test_support::process_scratch_path("raintrace_templates_test_" +
                                                           std::string{test->name()});
    fs::remove_all(m_root);
    fs::create_directories(m_root / "scene" / "inc");
    std::ofstream(m_root / "scene" / "inc" / "mine.inc") << "sphere{0,1}\n";
    std::ofstream(m_root / "outside.inc") << "#system(\"evil\")\n";
  }
  void TearDown() override { fs::remove_all(m_root); }
  fs::path scene_dir() const { return m_root / "scene"; }
  fs::path m_root;
};

// A template file with each line `#include "DIR/NAME.inc"` (a part of it, a path under
// templates/) replaced by that file's text, as povgen/CMakeLists.txt embeds it. (The files end
// their last line with a newline.)
std::string template_with_parts(const std::string& file_name) {
  const fs::path dir{RAINTRACE_TEMPLATES_DIR};
  std::istringstream lines(read_file_bytes(dir / file_name));
  const std::string include = "#include \"";
  std::string whole;
  for (std::string line; std::getline(lines, line);) {
    const bool is_part = line.starts_with(include) && line.find('/') != std::string::npos;
    whole +=
        is_part
            ? read_file_bytes(dir / line.substr(include.size(), line.size() - include.size() - 1))
            : line + "\n";
  }
  return whole;
}

TEST(Templates, BuiltinsAreEmbeddedAndMatchTheSourceFiles) {
  for (const std::string& name : builtin_environments()) {
    EXPECT_EQ(environment_template(name), template_with_parts(name + ".inc"))
        << name << ": re-run CMake after editing";
  }
  EXPECT_EQ(materials_template(),
            read_file_bytes(fs::path{RAINTRACE_TEMPLATES_DIR} / "raintrace_materials.inc"));
  EXPECT_NE(materials_template().find("#declare RT_DropMaterial"), std::string::npos);
}

TEST(Templates, NightStreetIsOneFileWithItsPartsInPlace) {
  // The output folder's environment.inc must render with POV-Ray alone: no include of a part
  // may be left for POV-Ray to look for, and each part's text is in it.
  const std::string& text = environment_template("night_street");
  EXPECT_EQ(text.find("#include \"night_street/"), std::string::npos);
  for (const auto& part :
       fs::directory_iterator(fs::path{RAINTRACE_TEMPLATES_DIR} / "night_street")) {
    EXPECT_NE(text.find(read_file_bytes(part.path())), std::string::npos) << part.path();
  }
  EXPECT_NE(text.find("#macro RT_StreetLight("), std::string::npos);
  EXPECT_NE(text.find("#macro RT_TrafficSignal("), std::string::npos);
}

TEST(Templates, NoSpotlightIsShadowless) {
  // POV-Ray 3.7 ignores a shadowless spotlight's cone (docs/povray-notes.md, "Lights"): such a
  // light would shine in every direction.
  for (const std::string& name : builtin_environments()) {
    const std::string text = environment_template(name);
    for (std::size_t at = text.find("light_source"); at != std::string::npos;
         at = text.find("light_source", at + 1)) {
      const std::size_t end = text.find('}', at);
      const std::string light = text.substr(at, end - at);
      EXPECT_FALSE(light.find("spotlight") != std::string::npos &&
                   light.find("shadowless") != std::string::npos)
          << name << ": " << light;
    }
  }
}

TEST(Templates, HostileEnvironmentNamesAreRejected) {
  for (const char* name : {"night_street\"", "#system(\"id\")", "../field", "field\n#fopen",
                           "field ", "/etc/passwd", ""}) {
    EXPECT_THROW(environment_template(name), std::invalid_argument) << name;
  }
}

TEST(Templates, MessagesNeverCarryControlCharacters) {
  try {
    environment_template("bad\nname\x1b[31m");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos);
    EXPECT_EQ(what.find('\x1b'), std::string::npos);
  }
}

TEST_F(UserInclude, IncludeInsideTheSceneFolderIsCopied) {
  EnvironmentParams env;
  env.include_path = "inc/mine.inc";
  EXPECT_EQ(environment_text(env, scene_dir()), "sphere{0,1}\n");
}

TEST_F(UserInclude, PathsLeavingTheSceneFolderAreRejected) {
  EnvironmentParams env;
  for (const std::string& path :
       std::vector<std::string>{"../outside.inc", "inc/../../outside.inc",
                                (m_root / "outside.inc").string(), "inc/missing.inc", "inc"}) {
    env.include_path = path;
    EXPECT_THROW(environment_text(env, scene_dir()), std::invalid_argument) << path;
  }
}

TEST_F(UserInclude, SymlinksOutOfTheSceneFolderAreRejected) {
  fs::create_symlink(m_root / "outside.inc", scene_dir() / "inc" / "link.inc");
  EnvironmentParams env;
  env.include_path = "inc/link.inc";
  EXPECT_THROW(environment_text(env, scene_dir()), std::invalid_argument);
}

TEST_F(UserInclude, EmptyPathUsesTheBuiltin) {
  EnvironmentParams env;
  env.name = "field";
  EXPECT_EQ(environment_text(env, scene_dir()), environment_template("field"));
}

}  // namespace
}  // namespace raintrace::povgen
