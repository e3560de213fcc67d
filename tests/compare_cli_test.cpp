// `raintrace compare` as a user runs it: exit codes 0 / 1 / 2, the table on stdout, --json,
// --diff and --html outputs, and error messages that name both files and their sizes.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "compare/image_io.h"

namespace {

namespace fs = std::filesystem;
using raintrace::compare::Image;

struct CommandResult {
  int exit_code = -1;
  std::string output;
};

CommandResult raintrace_compare(const std::string& args) {
  CommandResult r;
  FILE* pipe = popen((std::string("'" RAINTRACE_EXE "' compare ") + args + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf;
  while (fgets(buf.data(), int(buf.size()), pipe)) r.output += buf.data();
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

class CompareCli : public ::testing::Test {
 protected:
  void SetUp() override {
    m_dir = fs::path(::testing::TempDir()) /
            (std::string("raintrace_cli_") +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(m_dir);
    fs::create_directories(m_dir / "ref");
    fs::create_directories(m_dir / "out");
  }
  void TearDown() override { fs::remove_all(m_dir); }
  std::string path(const std::string& name) const { return "'" + (m_dir / name).string() + "'"; }
  void write(const std::string& name, const Image& img) const {
    raintrace::compare::write_image(m_dir / name, img);
  }
  fs::path m_dir;
};

Image grey(int w, int h, float v) { return Image(w, h, 3, v); }

TEST_F(CompareCli, IdenticalImagesExitZero) {
  write("ref/a.png", grey(32, 18, 0.5f));
  write("out/a.png", grey(32, 18, 0.5f));
  const auto r = raintrace_compare(path("ref/a.png") + " " + path("out/a.png"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("PASS"), std::string::npos) << r.output;
}

TEST_F(CompareCli, ThresholdsDecideBetweenFailAndWarn) {
  // 0.5 vs 0.6 (8-bit: 128/255 vs 153/255, a difference of 25/255 = 0.098).
  write("ref/a.png", grey(32, 18, 0.5f));
  write("out/a.png", grey(32, 18, 0.6f));
  const std::string files = path("ref/a.png") + " " + path("out/a.png");
  EXPECT_EQ(raintrace_compare(files).exit_code, 1);
  const auto warn = raintrace_compare(files + " --fail 0.1");
  EXPECT_EQ(warn.exit_code, 0) << warn.output;  // warnings do not fail
  EXPECT_NE(warn.output.find("WARN"), std::string::npos) << warn.output;
  EXPECT_EQ(raintrace_compare(files + " --fail 0.05 --fail-percent 100").exit_code, 0);
}

TEST_F(CompareCli, FoldersWriteJsonDiffAndHtmlAndMissingFramesFail) {
  write("ref/frame_0001.png", grey(32, 18, 0.5f));
  write("out/frame_0001.png", grey(32, 18, 0.5f));
  write("ref/frame_0002.png", grey(32, 18, 0.5f));
  const auto r =
      raintrace_compare(path("ref") + " " + path("out") + " --json " + path("r.json") + " --diff " +
                        path("diff") + " --html " + path("report/index.html"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("MISSING"), std::string::npos) << r.output;
  std::ifstream in(m_dir / "r.json");
  const auto doc = nlohmann::json::parse(in);
  EXPECT_EQ(doc["summary"]["missing"], 1);
  EXPECT_EQ(doc["frames"][0]["result"], "PASS");
  EXPECT_TRUE(fs::exists(m_dir / "diff/frame_0001_diff.png"));
  EXPECT_TRUE(fs::exists(m_dir / "report/index.html"));
  EXPECT_TRUE(fs::exists(m_dir / "report/index_files/0001_diff.png"));
  EXPECT_TRUE(fs::exists(m_dir / "report/index_files/0002_reference.png"));
}

TEST_F(CompareCli, DifferentSizesExitTwoNamingBothFilesAndSizes) {
  write("ref/a.png", grey(32, 18, 0.5f));
  write("out/a.png", grey(30, 18, 0.5f));
  const auto r = raintrace_compare(path("ref/a.png") + " " + path("out/a.png"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("32x18x3"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("30x18x3"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find((m_dir / "ref/a.png").string()), std::string::npos) << r.output;
  EXPECT_NE(r.output.find((m_dir / "out/a.png").string()), std::string::npos) << r.output;
}

/// A night frame in scene-linear light, as POV-Ray's EXRs hold it: a dark facade at 0.02 with
/// one lamp pixel at `lamp`.
Image night(float lamp) {
  Image img(32, 18, 3, 0.02f);
  for (int c = 0; c < 3; ++c) img.at(16, 9, c) = lamp;
  return img;
}

TEST_F(CompareCli, RenderFoldersComparePngsOrWithHdrTheirExrsDevelopedOrLinear) {
  // Two render folders (images/ holds each frame as EXR and PNG) with the same PNGs; the
  // candidate's EXR has its lamp 1 % brighter (300 → 303), which no viewer can see: the lamp is
  // white either way (Filmic clips only above 16.29), but in linear units 3.0 outweighs all else.
  write("ref/frame_0001.png", grey(32, 18, 0.25f));
  write("out/frame_0001.png", grey(32, 18, 0.25f));
  write("ref/frame_0001.exr", night(300.0f));
  write("out/frame_0001.exr", night(303.0f));
  const std::string folders = path("ref") + " " + path("out");
  const auto pngs = raintrace_compare(folders);
  EXPECT_EQ(pngs.exit_code, 0) << pngs.output;
  EXPECT_NE(pngs.output.find("frame_0001.png"), std::string::npos) << pngs.output;
  EXPECT_EQ(pngs.output.find("frame_0001.exr"), std::string::npos) << pngs.output;
  EXPECT_EQ(pngs.output.find("developed"), std::string::npos) << pngs.output;

  // --hdr: the EXRs, developed with the curve alone, equal to within one 8-bit step.
  const auto developed = raintrace_compare(folders + " --hdr --fail 0.0039");
  EXPECT_EQ(developed.exit_code, 0) << developed.output;
  EXPECT_NE(developed.output.find("frame_0001.exr"), std::string::npos) << developed.output;
  EXPECT_NE(developed.output.find("HDR input developed for comparison: raintrace develop: "
                                  "exposure_ev=0 view=filmic look=medium-high-contrast bloom=0 "
                                  "grain=0 vignette=0"),
            std::string::npos)
      << developed.output;
  const auto darker = raintrace_compare(folders + " --hdr --exposure-ev -1 --look high-contrast");
  EXPECT_NE(darker.output.find("exposure_ev=-1 view=filmic look=high-contrast"), std::string::npos)
      << darker.output;

  // --linear: the stored values; 3.0 fails an absolute threshold, passes a 2 % relative one.
  EXPECT_EQ(raintrace_compare(folders + " --hdr --linear --fail 0.01").exit_code, 1);
  const auto relative =
      raintrace_compare(folders + " --hdr --linear --fail 0.01 --fail-relative 0.02");
  EXPECT_EQ(relative.exit_code, 0) << relative.output;
}

TEST_F(CompareCli, UnreadableOrMissingInputExitsTwo) {
  write("ref/a.png", grey(8, 8, 0.5f));
  std::ofstream(m_dir / "out/a.png") << "not a png";
  EXPECT_EQ(raintrace_compare(path("ref/a.png") + " " + path("out/a.png")).exit_code, 2);
  EXPECT_EQ(raintrace_compare(path("ref/a.png") + " " + path("out/nope.png")).exit_code, 2);
  EXPECT_EQ(raintrace_compare(path("ref") + " " + path("ref/a.png")).exit_code, 2);
}

}  // namespace
