// The run budget: work and memory estimated before anything starts, and the messages that stop
// a run asking for too much.
#include "output/budget.h"

#include <gtest/gtest.h>

#include "povgen/frame_values.h"
#include "sim/frame.h"
#include "sim/lamp_rain.h"

namespace raintrace::output {
namespace {

constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;

SceneToExport scene(double rate, double far_m) {
  SceneToExport s;
  s.sim.rain.rate_mm_per_h = rate;
  s.sim.rain.far_m = far_m;
  s.frames = 48;
  return s;
}

std::string refusal(const Budget& b, const BudgetLimits& limits = {}) {
  try {
    check_budget(b, limits);
  } catch (const BudgetExceeded& e) {
    return e.what();
  }
  return "";
}

TEST(Budget, TheIssuesHeavyRainIsRefusedBeforeItStartsNamingTheKeys) {
  // rate_mm_per_h = 500, far_m = 25 passed the 50-million-drop check and then needed 4.8 GB
  // for one frame.
  const Budget b = estimate_budget(scene(500, 25), {1, 1}, 4);
  EXPECT_GT(b.total_bytes(), 4.5 * kGiB);
  const std::string why = refusal(b);
  EXPECT_NE(why.find("this scene needs about"), std::string::npos) << why;
  EXPECT_NE(why.find("lower [rain] far_m or rate_mm_per_h"), std::string::npos) << why;
  EXPECT_NE(why.find("--max-memory"), std::string::npos) << why;
  EXPECT_NE(why.find("(or --jobs)"), std::string::npos) << why;
  // Raising the limit as the message says lets it run.
  BudgetLimits more;
  more.max_memory_bytes = 64 * kGiB;
  EXPECT_EQ(refusal(b, more), "");
}

TEST(Budget, MemoryFollowsTheMeasuredModel) {
  // 1.1 million simulated drops measured 340 MiB at raintrace's peak rendering, and a dry
  // frame of night_street at 1280×720 107 MiB at POV-Ray's (budget.h, 2026-12-05): the
  // estimate may round up, never below.
  constexpr double kMiB = 1024.0 * 1024.0;
  const Budget b = estimate_budget(scene(500, 6), {1, 1}, 0);
  EXPECT_NEAR(b.drops, 1.1e6, 0.1e6);
  EXPECT_GE(b.simulation_bytes, 340.0 * kMiB);
  EXPECT_LE(b.simulation_bytes, 1.3 * 340.0 * kMiB);
  EXPECT_EQ(b.total_bytes(), b.simulation_bytes);  // export only: no POV-Ray
  const Budget rendering = estimate_budget(scene(500, 6), {1, 1}, 4);
  EXPECT_DOUBLE_EQ(rendering.total_bytes(), b.simulation_bytes + 4 * rendering.povray_bytes);
  SceneToExport dry = scene(0, 6);
  dry.look.width = 1280;
  dry.look.height = 720;
  const double povray = estimate_budget(dry, {1, 1}, 1).povray_bytes;
  EXPECT_GE(povray, 107.0 * kMiB);
  EXPECT_LE(povray, 1.3 * 107.0 * kMiB);
}

TEST(Budget, POVRaysMemoryFollowsTheStreaksLevelOfDetail) {
  // 160 bytes a drop in view were measured at the preview's streak threshold (0.01), ~550 with
  // every streak kept (budget.h). An unset min_streak_coverage is the quality's own threshold:
  // preview as measured, final (0.003) keeping more far streaks; 0 keeps them all.
  const auto per_view_drop = [](double coverage, povgen::Quality quality) {
    SceneToExport s = scene(50, 5);
    s.look.min_streak_coverage = coverage;
    s.look.quality = quality;
    const Budget b = estimate_budget(s, {1, 1}, 1);
    SceneToExport bare = s;
    bare.sim.rain.rate_mm_per_h = 0.0;
    const Budget none = estimate_budget(bare, {1, 1}, 1);
    return (b.povray_bytes - none.povray_bytes) / b.drops_in_view;
  };
  EXPECT_NEAR(per_view_drop(-1.0, povgen::Quality::preview), 160.0, 1.0);
  EXPECT_NEAR(per_view_drop(0.01, povgen::Quality::final), 160.0, 1.0);
  EXPECT_NEAR(per_view_drop(-1.0, povgen::Quality::final), 160.0 * 0.01 / 0.003, 1.0);
  EXPECT_NEAR(per_view_drop(0.0, povgen::Quality::preview), 600.0, 1.0);
  EXPECT_NEAR(per_view_drop(0.1, povgen::Quality::preview), 16.0, 1.0);
}

TEST(Budget, CountsTheDropsSimulatedAroundTheLampsInView) {
  SceneToExport s = scene(5, 6);
  const Budget without = estimate_budget(s, {1, 1}, 0);
  s.sim.lamps = {{1.0, 4.0, 15.0}};  // ahead of the default camera, in view
  s.sim.rain.lamp_reach_m = 3.0;
  const Budget with = estimate_budget(s, {1, 1}, 0);
  const double lamp_drops = sim::LampRain::estimate(s.sim).drops;
  EXPECT_GT(lamp_drops, 0.0);
  EXPECT_DOUBLE_EQ(with.drops, without.drops + lamp_drops);
  EXPECT_GT(with.simulation_bytes, without.simulation_bytes);
  const std::string why = refusal(with, {.max_memory_bytes = 1e6});
  EXPECT_NE(why.find("lower [rain] far_m or rate_mm_per_h (or lamp_reach_m)"), std::string::npos)
      << why;
  EXPECT_EQ(refusal(without, {.max_memory_bytes = 1e6}).find("lamp_reach_m"), std::string::npos);
}

TEST(Budget, CountsTheLampsDropsAFrameDrawsAsPovgenThinsThem) {
  // The lamps' drops lie 15 m and more away, where povgen thins most far streaks: POV-Ray's
  // memory follows the few it draws, not the ball's hundreds of thousands (budgeted until
  // 2026-12-05, 2.5 GB for heavy_rain where POV-Ray peaked at 76 MB). The sampled estimate must
  // match what a real frame of the lamps' rain draws.
  SceneToExport s = scene(50, 5);
  s.sim.lamps = {{1.0, 4.5, 18.0}};
  s.sim.rain.lamp_reach_m = 3.0;
  s.sim.threads = 2;
  s.look.camera = s.sim.camera;
  s.look.width = 640;
  s.look.height = 360;
  for (const povgen::Quality quality : {povgen::Quality::preview, povgen::Quality::final}) {
    s.look.quality = quality;
    const Budget b = estimate_budget(s, {1, 1}, 1);
    sim::LampRain rain(s.sim);
    sim::Frame frame;
    frame.index = 1;
    rain.add_drops(frame.drops);
    const povgen::FrameValues values = povgen::build_frame_values(frame, s.look);
    const auto drawn = static_cast<double>(values.drops.size() + values.streaks.size());
    ASSERT_GT(drawn, 100.0);
    EXPECT_NEAR(b.lamp_drops_drawn, drawn, 0.2 * drawn);
    // A few percent of the drops the ball holds in view.
    EXPECT_LT(drawn, 0.25 * static_cast<double>(frame.drops.size()));
  }
}

TEST(Budget, AFrameRateOfAlmostNothingIsRefusedForItsWork) {
  SceneToExport s = scene(5, 12);
  s.look.fps = 1e-9;  // frame 2 lies at 1e9 s: 5e11 substeps
  const Budget b = estimate_budget(s, {1, 2}, 1);
  EXPECT_GT(b.substeps, 4e11);
  const std::string why = refusal(b);
  EXPECT_NE(why.find("drop-steps of simulation"), std::string::npos) << why;
  EXPECT_NE(why.find("raise [simulation] substep_s or [output] fps"), std::string::npos) << why;
  EXPECT_NE(why.find("--max-drop-steps"), std::string::npos) << why;
  EXPECT_NE(why.find("years"), std::string::npos) << why;
  // Frame 1 alone needs only the prewarm.
  EXPECT_EQ(refusal(estimate_budget(s, {1, 1}, 1)), "");
}

TEST(Budget, TheDefaultSceneFitsEasily) {
  const Budget b = estimate_budget(scene(5, 12), {1, 48}, 4);
  EXPECT_EQ(refusal(b), "");
  EXPECT_LT(b.total_bytes(), 1.0 * kGiB);
  EXPECT_LT(b.drop_steps, 1e10);
}

TEST(Budget, ByteSizesReadAsPeopleWriteThem) {
  EXPECT_EQ(parse_byte_size("2000000"), 2000000.0);
  EXPECT_EQ(parse_byte_size("512M"), 512.0 * 1024 * 1024);
  EXPECT_EQ(parse_byte_size("1.5G"), 1.5 * kGiB);
  EXPECT_EQ(parse_byte_size("8GB"), 8 * kGiB);
  EXPECT_EQ(parse_byte_size("8gib"), 8 * kGiB);
  EXPECT_EQ(parse_byte_size("300k"), 300.0 * 1024);
  EXPECT_FALSE(parse_byte_size(""));
  EXPECT_FALSE(parse_byte_size("G"));
  EXPECT_FALSE(parse_byte_size("-1G"));
  EXPECT_FALSE(parse_byte_size("0"));
  EXPECT_FALSE(parse_byte_size("8 potatoes"));
  EXPECT_EQ(format_bytes(1.5 * kGiB), "1.5 GB");
  EXPECT_EQ(format_bytes(300.0 * 1024 * 1024), "300 MB");
}

}  // namespace
}  // namespace raintrace::output
