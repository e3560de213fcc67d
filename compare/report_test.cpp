// Table, JSON and HTML text for a hand-built report.
#include <gtest/gtest.h>

#include <limits>
#include <nlohmann/json.hpp>

#include "compare/report_html.h"
#include "compare/report_json.h"
#include "compare/report_table.h"

namespace raintrace::compare {
namespace {

CompareReport sample_report() {
  CompareReport r;
  r.a = "ref";
  r.b = "out";
  r.folders = true;
  FrameResult same;
  same.name = "frame_0001.png";
  same.a = "ref/frame_0001.png";
  same.b = "out/frame_0001.png";
  same.metrics.pixels = 100;
  same.asset_reference = "0001_reference.png";
  same.asset_candidate = "0001_candidate.png";
  same.asset_diff = "0001_diff.png";
  FrameResult bad = same;
  bad.name = "frame_<2>.png";
  bad.metrics.mean_error = 0.125;
  bad.metrics.max_error = 0.5;
  bad.metrics.max_x = 7;
  bad.metrics.rmse = 0.25;
  bad.metrics.psnr = 12.0412;
  bad.metrics.ssim = 0.75;
  bad.metrics.fail_pixels = 10;
  bad.metrics.fail_percent = 10.0;
  bad.metrics.verdict = Verdict::fail;
  FrameResult missing;
  missing.name = "frame_0003.png";
  missing.a = "ref/frame_0003.png";
  missing.status = FrameStatus::missing_b;
  r.frames = {same, bad, missing};
  return r;
}

TEST(Report, JsonHasEveryNumberAndNullForInfinity) {
  const auto doc = nlohmann::json::parse(to_json(sample_report()));
  ASSERT_EQ(doc["frames"].size(), 3u);
  EXPECT_TRUE(doc["frames"][0]["psnr"].is_null());  // identical: PSNR infinite
  EXPECT_EQ(doc["frames"][0]["result"], "PASS");
  EXPECT_EQ(doc["frames"][1]["rmse"], 0.25);
  EXPECT_EQ(doc["frames"][1]["max_pixel"]["x"], 7);
  EXPECT_EQ(doc["frames"][1]["fail_percent"], 10.0);
  EXPECT_EQ(doc["frames"][1]["result"], "FAIL");
  EXPECT_EQ(doc["frames"][2]["result"], "MISSING");
  EXPECT_TRUE(doc["frames"][2]["candidate"].is_null());
  EXPECT_EQ(doc["summary"]["passed"], 1);
  EXPECT_EQ(doc["summary"]["failed"], 1);
  EXPECT_EQ(doc["summary"]["missing"], 1);
  EXPECT_EQ(doc["thresholds"]["fail"], 1e-6);
  EXPECT_TRUE(doc["thresholds"]["hard_fail"].is_null());
}

TEST(Report, NonFinitePixelsAreReportedAsSuch) {
  CompareReport r = sample_report();
  Metrics& m = r.frames[1].metrics;
  m.nonfinite_pixels = 2;
  m.mean_error = m.rmse = m.psnr = m.ssim = std::numeric_limits<double>::quiet_NaN();
  m.max_error = std::numeric_limits<double>::infinity();
  const auto doc = nlohmann::json::parse(to_json(r));
  EXPECT_EQ(doc["frames"][1]["nonfinite_pixels"], 2);
  EXPECT_TRUE(doc["frames"][1]["mean_error"].is_null());
  EXPECT_EQ(doc["frames"][0]["nonfinite_pixels"], 0);
  const std::string table = format_table(r);
  EXPECT_NE(table.find("nan"), std::string::npos) << table;
  EXPECT_NE(table.find("frame_<2>.png: 2 pixel(s) hold NaN or Inf where the other image does not"),
            std::string::npos)
      << table;
}

TEST(Report, TableHasOneAlignedRowPerFrameAndASummary) {
  const std::string table = format_table(sample_report());
  std::vector<std::string> lines;
  for (std::size_t start = 0, end; (end = table.find('\n', start)) != std::string::npos;
       start = end + 1)
    lines.push_back(table.substr(start, end - start));
  ASSERT_EQ(lines.size(), 5u);  // header, 3 frames, summary
  EXPECT_NE(lines[1].find("inf"), std::string::npos);
  EXPECT_NE(lines[1].find("PASS"), std::string::npos);
  EXPECT_NE(lines[2].find("FAIL"), std::string::npos);
  EXPECT_NE(lines[2].find("0.25"), std::string::npos);
  // Aligned columns: the verdict and the PSNR column start at the same place on every row.
  EXPECT_EQ(lines[0].find("result"), lines[1].find("PASS"));
  EXPECT_EQ(lines[1].find("PASS"), lines[2].find("FAIL"));
  EXPECT_EQ(lines[0].find("PSNR") + 4, lines[1].find("inf") + 3);
  EXPECT_NE(lines[3].find("MISSING"), std::string::npos);
  EXPECT_NE(lines[4].find("1 PASS, 1 FAIL, 1 MISSING"), std::string::npos) << lines[4];
}

TEST(Report, HtmlEscapesNamesAndLinksTheAssets) {
  const std::string html = to_html(sample_report(), "report_files");
  EXPECT_NE(html.find("frame_&lt;2&gt;.png"), std::string::npos);
  EXPECT_EQ(html.find("frame_<2>"), std::string::npos);
  EXPECT_NE(html.find("src=\"report_files/0001_reference.png\""), std::string::npos);
  EXPECT_NE(html.find("src=\"report_files/0001_diff.png\""), std::string::npos);
  EXPECT_NE(html.find("no image"), std::string::npos);  // the missing frame's candidate
  EXPECT_EQ(html.find("http"), std::string::npos);      // nothing from the network
  EXPECT_EQ(html_assets_dir("/x/y/report.html"), std::filesystem::path("/x/y/report_files"));
}

}  // namespace
}  // namespace raintrace::compare
