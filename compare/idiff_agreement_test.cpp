// Our metrics against OpenImageIO's own `idiff` on the same files: RMSE, PSNR, mean and max
// error (with its pixel) and the pass/warn/fail verdict under the same thresholds.
#include <gtest/gtest.h>

#include <fmt/core.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <regex>
#include <string>

#include "compare/compare_run.h"
#include "compare/test_files.h"

namespace raintrace::compare {
namespace {

namespace fs = std::filesystem;
constexpr const char* kIdiff = "/usr/bin/idiff";

struct IdiffResult {
  int exit_code = -1;
  std::string output;
};

IdiffResult run_idiff(const std::string& args) {
  IdiffResult r;
  const std::string command = std::string(kIdiff) + " -v " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf;
  while (fgets(buf.data(), int(buf.size()), pipe)) r.output += buf.data();
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

double field(const std::string& text, const std::string& name) {
  std::smatch m;
  if (!std::regex_search(text, m, std::regex(name + R"(\s*=\s*([-+0-9.eEinf]+))"))) {
    ADD_FAILURE() << "no '" << name << "' in idiff output:\n" << text;
    return 0;
  }
  return std::stod(m[1]);
}

// Writes two images built in ImageBufs: a smooth pattern, and the same with a quarter of its
// values moved by −8..7 steps of 1/255 (so 8-bit files hold them exactly) and one large error.
void write_pair(const fs::path& a, const fs::path& b, OIIO::TypeDesc format, int nchannels,
                unsigned seed) {
  const int w = 37, h = 23;
  OIIO::ImageSpec spec(w, h, nchannels, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf A(spec), B(spec);
  unsigned state = seed * 2654435761u + 1u;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (int c = 0; c < nchannels; ++c) {
        const float v = float((x * 5 + y * 9 + c * 31) % 200 + 20) / 255.0f;
        state = state * 1664525u + 1013904223u;
        const int step = int(state >> 28) - 8;
        float pa[8], pb[8];
        A.getpixel(x, y, pa, nchannels);
        B.getpixel(x, y, pb, nchannels);
        pa[c] = v;
        pb[c] = ((state >> 8) % 4 == 0) ? v + float(step) / 255.0f : v;
        if (x == 30 && y == 17 && c == nchannels - 1)
          pb[c] = v + (v > 0.5f ? -40.0f : 40.0f) / 255.0f;
        A.setpixel(x, y, pa, nchannels);
        B.setpixel(x, y, pb, nchannels);
      }
    }
  }
  ASSERT_TRUE(A.write(a.string(), format)) << A.geterror();
  ASSERT_TRUE(B.write(b.string(), format)) << B.geterror();
}

class IdiffAgreement : public ::testing::TestWithParam<std::tuple<std::string, int>> {
 protected:
  void SetUp() override {
    if (!fs::exists(kIdiff))
      GTEST_SKIP() << kIdiff << " not found (apt-get install openimageio-tools)";
  }
};

TEST_P(IdiffAgreement, RmsePsnrMeanMaxAndVerdictMatch) {
  const auto& [ext, nchannels] = GetParam();
  testing_support::TempDir tmp;
  const fs::path a = tmp.path() / ("a." + ext), b = tmp.path() / ("b." + ext);
  write_pair(a, b, ext == "png" ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT, nchannels,
             unsigned(nchannels));
  // The same thresholds on both sides: 3/255 per value, 5 % of pixels may fail.
  CompareOptions options;
  options.hdr.linear = true;  // idiff compares stored values: so do we, for EXR too
  options.thresholds.fail = 3.0 / 255.0 + 1e-4;
  options.thresholds.warn = 1.0 / 255.0 + 1e-4;
  options.thresholds.fail_percent = 5.0;
  const auto report = compare_paths(a, b, options);
  ASSERT_EQ(report.frames.size(), 1u);
  ASSERT_EQ(report.frames[0].status, FrameStatus::compared) << report.frames[0].error;
  const Metrics& m = report.frames[0].metrics;

  const auto idiff =
      run_idiff(fmt::format("-fail {} -warn {} -failpercent 5 {} {}", options.thresholds.fail,
                            options.thresholds.warn, a.string(), b.string()));
  // idiff prints 6 significant digits.
  EXPECT_NEAR(field(idiff.output, "Mean error"), m.mean_error, 1e-5 * m.mean_error);
  EXPECT_NEAR(field(idiff.output, "RMS error"), m.rmse, 1e-5 * m.rmse);
  EXPECT_NEAR(field(idiff.output, "Peak SNR"), m.psnr, 1e-4 * m.psnr);
  EXPECT_NEAR(field(idiff.output, "Max error"), m.max_error, 1e-5 * m.max_error);
  // The planted large error: 40/255 at (30, 17) in the last channel.
  EXPECT_NEAR(m.max_error, 40.0 / 255.0, 1e-6);
  EXPECT_NE(idiff.output.find(fmt::format("@ ({}, {}", m.max_x, m.max_y)), std::string::npos)
      << idiff.output;
  std::smatch counts;
  ASSERT_TRUE(std::regex_search(
      idiff.output, counts, std::regex(R"((\d+) pixels \([^)]*\) over [^\n]*\n\s*(\d+) pixels)")))
      << idiff.output;
  EXPECT_EQ(std::stoul(counts[1]), m.warn_pixels);
  EXPECT_EQ(std::stoul(counts[2]), m.fail_pixels);
  // idiff exits 0 PASS, 1 WARNING, 2 FAILURE.
  const int expected = m.verdict == Verdict::pass ? 0 : m.verdict == Verdict::warn ? 1 : 2;
  EXPECT_EQ(idiff.exit_code, expected) << idiff.output;
}

INSTANTIATE_TEST_SUITE_P(Formats, IdiffAgreement,
                         ::testing::Values(std::make_tuple(std::string("png"), 3),
                                           std::make_tuple(std::string("png"), 4),
                                           std::make_tuple(std::string("exr"), 3),
                                           std::make_tuple(std::string("tif"), 1)));

TEST(IdiffAgreementVerdict, FailPercentBoundaryAgrees) {
  if (!fs::exists(kIdiff)) GTEST_SKIP() << kIdiff << " not found";
  // 10×10 grey, exactly 5 pixels off by 0.2: at 5 % both pass (5 > 5 is false), at 4 % both
  // fail — the "strictly more than" rule of idiff.
  testing_support::TempDir tmp;
  OIIO::ImageBuf A(OIIO::ImageSpec(10, 10, 3, OIIO::TypeDesc::FLOAT)), B;
  OIIO::ImageBufAlgo::fill(A, {0.5f, 0.5f, 0.5f});
  B.copy(A);
  const float off[3] = {0.7f, 0.5f, 0.5f};
  for (int i = 0; i < 5; ++i) B.setpixel(i, 2 * i, off, 3);
  const fs::path a = tmp.path() / "a.exr", b = tmp.path() / "b.exr";
  ASSERT_TRUE(A.write(a.string()));
  ASSERT_TRUE(B.write(b.string()));
  for (double pct : {5.0, 4.0}) {
    CompareOptions options;
    options.hdr.linear = true;  // idiff compares stored values
    options.thresholds.fail = 0.1;
    options.thresholds.warn = 0.1;
    options.thresholds.fail_percent = pct;
    options.thresholds.warn_percent = pct;
    const Verdict ours = compare_paths(a, b, options).frames[0].metrics.verdict;
    const auto idiff =
        run_idiff(fmt::format("-fail 0.1 -warn 0.1 -failpercent {0} -warnpercent {0} {1} {2}", pct,
                              a.string(), b.string()));
    EXPECT_EQ(ours, pct == 5.0 ? Verdict::pass : Verdict::fail);
    EXPECT_EQ(idiff.exit_code, ours == Verdict::pass ? 0 : 2) << idiff.output;
  }
}

}  // namespace
}  // namespace raintrace::compare
