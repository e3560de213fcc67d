// Progress text.
#include "render/progress_format.h"

#include <gtest/gtest.h>

namespace raintrace::render {
namespace {

TEST(ProgressFormat, BarFillsInProportionToFinishedFrames) {
  RenderProgress p;
  p.total = 48;
  p.done = 11;
  p.failed = 1;
  p.elapsed_seconds = 12.0;
  p.eta_seconds = 36.0;
  // 12 of 48 finished = 1/4 of a 20-character bar = 5 '#'.
  EXPECT_EQ(format_progress_bar(p, 20),
            "[#####---------------]   12/48 frames  1 failed  00:12 elapsed  ETA 00:36");
  EXPECT_EQ(format_progress_line(p),
            "render: 11/48 frames done, 1 failed, 12.0 s elapsed, ETA 36 s");
}

TEST(ProgressFormat, ExportedCountAppearsOnlyWhileTheSameRunExports) {
  RenderProgress p;
  p.total = 48;
  p.done = 12;
  p.exported = 30;
  p.export_total = 48;
  p.elapsed_seconds = 12.3;
  p.eta_seconds = 36.0;
  EXPECT_EQ(format_progress_bar(p, 4),
            "[#---]   12/48 frames  30/48 exported  0 failed  00:12 elapsed  ETA 00:36");
  EXPECT_EQ(format_progress_line(p),
            "render: 12/48 frames done, 30/48 exported, 0 failed, 12.3 s elapsed, ETA 36 s");
  p.export_total = 0;  // rendering an exported folder
  EXPECT_EQ(format_progress_line(p),
            "render: 12/48 frames done, 0 failed, 12.3 s elapsed, ETA 36 s");
}

TEST(ProgressFormat, UnknownEtaAndLongClocks) {
  RenderProgress p;
  p.total = 2;
  EXPECT_NE(format_progress_bar(p, 4).find("ETA --:--"), std::string::npos);
  EXPECT_NE(format_progress_line(p).find("ETA unknown"), std::string::npos);
  EXPECT_EQ(format_clock(3725.0), "1:02:05");  // 3600 + 2·60 + 5
  EXPECT_EQ(format_clock(59.6), "01:00");
}

}  // namespace
}  // namespace raintrace::render
