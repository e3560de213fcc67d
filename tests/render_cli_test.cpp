// `raintrace render` end to end, as a user runs it: exit codes, progress lines when stderr is
// not a terminal, failure reports, SIGINT and SIGKILL in the middle of a render.
#include <fmt/core.h>
#include <gtest/gtest.h>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <thread>

#include "output/image_check.h"
#include "output/manifest.h"
#include "render/povray_command.h"
#include "render/povray_runner.h"
#include "render/process.h"
#include "render/test_folder.h"
#include "tests/cli_test_support.h"

namespace raintrace::render {
namespace {

using output::image_is_complete;
using output::read_manifest;

using raintrace::clitest::raintrace_spec;
using raintrace::clitest::read_all;
using raintrace::clitest::Run;
using raintrace::clitest::run_raintrace;
using raintrace::clitest::write_scene;

int rendered_in_manifest(const std::filesystem::path& dir) {
  try {
    int n = 0;
    for (const auto& f : read_manifest(dir / "manifest.json").frames) {
      n += f.image.status == output::FrameStatus::rendered ? 1 : 0;
    }
    return n;
  } catch (const std::exception&) {
    return 0;
  }
}

class PovrayRenderCli : public testing::PovrayTest {};

TEST_F(PovrayRenderCli, RendersAFolderPrintsPlainProgressLinesAndTheOutputs) {
  const auto dir = testing::fresh_test_dir("cli_ok");
  testing::write_test_folder(dir / "out", {.frames = 4});
  const auto r = run_raintrace({"render", (dir / "out").string(), "--jobs", "2"}, dir / "log");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  // Not a terminal: one plain line per finished frame, no carriage returns or escapes.
  for (int k = 1; k <= 4; ++k) {
    EXPECT_NE(r.output.find("render: " + std::to_string(k) + "/4 frames done"), std::string::npos)
        << r.output;
  }
  EXPECT_EQ(r.output.find('\r'), std::string::npos);
  EXPECT_EQ(r.output.find("\x1b["), std::string::npos);
  EXPECT_NE(r.output.find("contact sheet: "), std::string::npos);
  EXPECT_TRUE(image_is_complete(dir / "out/contact_sheet.png", 4 + 2 * (64 + 4),
                                4 + 2 * (36 + 12 + 4)));  // 4 frames → 2×2 grid, labels 12 px
  for (int f = 1; f <= 4; ++f) {
    EXPECT_TRUE(image_is_complete(dir / "out" / final_image_name(Pass::image, f), 64, 36));
  }
  // Second run: nothing to do, still success.
  const auto again = run_raintrace({"render", (dir / "out").string()}, dir / "log2");
  EXPECT_EQ(again.exit_code, 0);
  EXPECT_NE(again.output.find("0 frames rendered, 4 up to date, 0 failed"), std::string::npos)
      << again.output;
}

TEST_F(PovrayRenderCli, FailedFrameIsReportedWithCommandExitCodeAndPovrayErrorAndExitsOne) {
  const auto dir = testing::fresh_test_dir("cli_fail");
  testing::write_test_folder(dir / "out", {.frames = 5});
  testing::replace_frame(dir / "out", 3, "#include \"scene.inc\"\nsphere { <0,0,0> oops }\n");
  const auto r = run_raintrace({"render", (dir / "out").string(), "--no-movie"}, dir / "log");
  EXPECT_EQ(r.exit_code, 1) << r.output;  // cli/exit_codes.h: failed
  EXPECT_NE(r.output.find("frame 3 failed: POV-Ray exited with code 1"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("command: cd "), std::string::npos);
  EXPECT_NE(r.output.find("povray scene.ini"), std::string::npos);
  EXPECT_NE(r.output.find("File 'frames/frame_0003.pov' line 2: Parse Error"), std::string::npos);
  EXPECT_NE(r.output.find("4 frames rendered, 0 up to date, 1 failed"), std::string::npos);
}

// On a loaded machine POV-Ray sometimes gives up before reading anything (seen in CI: one frame
// of a test failed, its log holding that one line). Nothing was traced, so raintrace starts it
// again on the same frames instead of failing them.
TEST_F(PovrayRenderCli, APovrayThatDidNotStartIsStartedAgainOnTheSameFrames) {
  const auto dir = testing::fresh_test_dir("cli_not_started");
  testing::write_test_folder(dir / "out", {.frames = 1});
  const auto bin = testing::povray_that_does_not_start(dir, "scene.ini", kPovrayStartAttempts - 1);
  const auto r = run_raintrace({"render", (dir / "out").string(), "--no-movie"}, dir / "log",
                               testing::path_with(bin));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("1 frames rendered, 0 up to date, 0 failed"), std::string::npos)
      << r.output;
  // Three starts that gave up, then the one that rendered the frame.
  EXPECT_EQ(read_all(dir / "starts"), std::to_string(kPovrayStartAttempts) + "\n");
  EXPECT_TRUE(image_is_complete(dir / "out" / final_image_name(Pass::image, 1), 64, 36));
}

// A POV-Ray that never starts fails its frames after kPovrayStartAttempts starts each, and says
// why in the failure report.
TEST_F(PovrayRenderCli, APovrayThatNeverStartsFailsTheFrameAndSaysWhy) {
  const auto dir = testing::fresh_test_dir("cli_never_started");
  testing::write_test_folder(dir / "out", {.frames = 1});
  const auto bin = testing::povray_that_does_not_start(dir, "scene.ini", 1000);
  const auto r = run_raintrace({"render", (dir / "out").string(), "--no-movie"}, dir / "log",
                               testing::path_with(bin));
  EXPECT_EQ(r.exit_code, 1) << r.output;  // cli/exit_codes.h: failed
  EXPECT_NE(r.output.find(fmt::format("POV-Ray did not start, {} times: {}", kPovrayStartAttempts,
                                      kPovrayStartupTimeout)),
            std::string::npos)
      << r.output;
  EXPECT_EQ(read_all(dir / "starts"), std::to_string(kPovrayStartAttempts) + "\n");
}

TEST_F(PovrayRenderCli, MissingPovrayIsOneClearLineAndExitTwo) {
  const auto dir = testing::fresh_test_dir("cli_nopov");
  testing::write_test_folder(dir / "out", {.frames = 1});
  const auto r = run_raintrace({"render", (dir / "out").string()}, dir / "log",
                               {{"PATH", (dir / "empty-path").string()}});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.output,
            "raintrace: error: POV-Ray not found: install it with `sudo apt-get install povray`\n");
}

/// What a killed run left: the frames whose EXR is complete at its final name (with its
/// modification time: the manifest records it, or the next run adopts it, since it is newer
/// than its inputs), and how many of those the manifest records as developed too.
struct Finished {
  std::map<int, std::filesystem::file_time_type> exr;
  int developed = 0;
};

Finished finished_images(const std::filesystem::path& out) {
  Finished finished;
  for (const auto& f : read_manifest(out / "manifest.json").frames) {
    if (f.image.status == output::FrameStatus::rendered) {
      EXPECT_TRUE(image_is_complete(out / f.image.path, 64, 36)) << f.image.path;
    }
    if (!image_is_complete(out / f.image.path, 64, 36)) continue;
    finished.exr[f.number] = std::filesystem::last_write_time(out / f.image.path);
    if (f.image.status == output::FrameStatus::rendered && !f.developed.develop_hash.empty() &&
        f.developed.source_hash == f.image.file_hash) {
      ++finished.developed;
      EXPECT_TRUE(image_is_complete(out / f.developed.path, 64, 36)) << f.developed.path;
    }
  }
  return finished;
}

/// A re-run after a kill rendered exactly the frames that were not finished, developed the
/// rendered ones it had not developed, left the finished EXRs untouched, and every one of the
/// `frames` EXRs and PNGs is now complete.
void expect_rerun_redid_only_unfinished(const Run& rerun, const std::filesystem::path& out,
                                        const Finished& finished, int frames) {
  EXPECT_EQ(rerun.exit_code, 0) << rerun.output;
  const int redo = frames - static_cast<int>(finished.exr.size());
  const int develop = static_cast<int>(finished.exr.size()) - finished.developed;
  const std::string developed = develop > 0 ? fmt::format("{} developed only, ", develop) : "";
  EXPECT_NE(rerun.output.find(fmt::format("{} frames rendered, {}{} up to date", redo, developed,
                                          finished.developed)),
            std::string::npos)
      << rerun.output;
  for (const auto& [frame, mtime] : finished.exr) {
    EXPECT_EQ(std::filesystem::last_write_time(out / final_image_name(Pass::image, frame)), mtime)
        << "frame " << frame << " was rendered again";
  }
  for (int f = 1; f <= frames; ++f) {
    EXPECT_TRUE(image_is_complete(out / final_image_name(Pass::image, f), 64, 36)) << f;
    EXPECT_TRUE(image_is_complete(out / developed_image_name(f), 64, 36)) << f;
  }
}

std::unique_ptr<ChildProcess> start_slow_render(const std::filesystem::path& dir, int frames_done) {
  testing::write_test_folder(dir / "out", {.frames = 10, .spheres = 6000});
  auto child = std::make_unique<ChildProcess>(
      raintrace_spec({"render", (dir / "out").string(), "--jobs", "1", "--no-movie"}, dir / "log"));
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (rendered_in_manifest(dir / "out") < frames_done &&
         std::chrono::steady_clock::now() < deadline && !child->poll()) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return child;
}

TEST_F(PovrayRenderCli, SigkillHalfwayThenRerunFinishesWithoutRedoingFinishedFrames) {
  const auto dir = testing::fresh_test_dir("cli_kill");
  auto child = start_slow_render(dir, 3);
  ASSERT_TRUE(child);
  ASSERT_FALSE(child->poll().has_value()) << read_all(dir / "log");
  ::kill(child->pid(), SIGKILL);
  EXPECT_EQ(child->wait(), 128 + SIGKILL);

  const Finished finished = finished_images(dir / "out");
  ASSERT_GE(finished.exr.size(), 3U);
  ASSERT_LT(finished.exr.size(), 10U);
  // Whatever the killed run left at final names is complete (EXR and PNG); the rest only at
  // temp names.
  for (int f = 1; f <= 10; ++f) {
    for (const auto& image :
         {dir / "out" / final_image_name(Pass::image, f), dir / "out" / developed_image_name(f)}) {
      if (std::filesystem::exists(image)) {
        EXPECT_TRUE(image_is_complete(image, 64, 36)) << image;
      }
    }
  }

  const auto r = run_raintrace({"render", (dir / "out").string(), "--no-movie"}, dir / "log2");
  expect_rerun_redid_only_unfinished(r, dir / "out", finished, 10);
  EXPECT_FALSE(std::filesystem::exists(dir / "out/images/.tmp") &&
               !std::filesystem::is_empty(dir / "out/images/.tmp"));
}

TEST_F(PovrayRenderCli, SigintStopsPovrayKeepsFramesAndSaysHowToResume) {
  const auto dir = testing::fresh_test_dir("cli_int");
  auto child = start_slow_render(dir, 2);
  ASSERT_FALSE(child->poll().has_value()) << read_all(dir / "log");
  ::kill(child->pid(), SIGINT);
  EXPECT_EQ(child->wait(), 128 + SIGINT);
  const std::string out = read_all(dir / "log");
  EXPECT_NE(out.find("interrupted by SIGINT"), std::string::npos) << out;
  EXPECT_NE(out.find("run the same command again to resume"), std::string::npos);
  EXPECT_GE(rendered_in_manifest(dir / "out"), 2);
}

std::string frame_file(const std::filesystem::path& out, int frame) {
  return read_all(out / fmt::format("frames/frame_{:04d}.pov", frame));
}

TEST_F(PovrayRenderCli, SceneFileIsExportedWhileRenderingIntoTheSameFilesAsAPlainExport) {
  const auto dir = testing::fresh_test_dir("cli_overlap");
  const auto scene = write_scene(dir, 6);
  const auto r = run_raintrace(
      {"render", scene.string(), "-o", (dir / "a").string(), "--jobs", "3", "--no-movie"},
      dir / "log_a");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("exported, 0 failed"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("export: all 6 frames written"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("6 frames rendered, 0 up to date, 0 failed"), std::string::npos);
  const auto one_job = run_raintrace(
      {"render", scene.string(), "-o", (dir / "b").string(), "--jobs", "1", "--no-movie"},
      dir / "log_b");
  EXPECT_EQ(one_job.exit_code, 0) << one_job.output;
  const auto plain =
      run_raintrace({"export", scene.string(), "-o", (dir / "c").string()}, dir / "log_c");
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  // Byte-identical frames whatever the overlap and the number of POV-Ray processes.
  for (int f = 1; f <= 6; ++f) {
    const std::string expected = frame_file(dir / "c", f);
    EXPECT_FALSE(expected.empty());
    EXPECT_EQ(frame_file(dir / "a", f), expected) << "frame " << f;
    EXPECT_EQ(frame_file(dir / "b", f), expected) << "frame " << f;
    EXPECT_TRUE(image_is_complete(dir / "a" / final_image_name(Pass::image, f), 64, 36)) << f;
  }
  EXPECT_EQ(read_all(dir / "a/scene.inc"), read_all(dir / "c/scene.inc"));
  const auto manifest = read_manifest(dir / "a/manifest.json");
  const auto exported = read_manifest(dir / "c/manifest.json");
  ASSERT_EQ(manifest.frames.size(), 6U);
  ASSERT_EQ(exported.frames.size(), 6U);
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(manifest.frames[i].image.status, output::FrameStatus::rendered);
    EXPECT_EQ(manifest.frames[i].input_hash, exported.frames[i].input_hash);
    EXPECT_EQ(manifest.frames[i].image.rendered_hash, exported.frames[i].input_hash);
  }
  // The same command again: everything is up to date, nothing is ray-traced.
  const auto again = run_raintrace(
      {"render", scene.string(), "-o", (dir / "a").string(), "--no-movie"}, dir / "log_a2");
  EXPECT_EQ(again.exit_code, 0) << again.output;
  EXPECT_NE(again.output.find("0 frames rendered, 6 up to date, 0 failed"), std::string::npos)
      << again.output;
}

// A still tried alone (`--frames 5`) stays rendered when the run around it comes: its frame is
// the same text whichever frames were simulated into snapshots before it. Until 2026-12-02 the
// splash droplets came out in another order, so frame 5 was exported anew and traced again.
TEST_F(PovrayRenderCli, AFrameRenderedAloneIsUpToDateInALaterRunOfARangeHoldingIt) {
  const auto dir = testing::fresh_test_dir("cli_alone_then_range");
  // Heavy rain on the ground in front: crowns throw droplets, near and far.
  const auto scene = dir / "splashes.toml";
  std::ofstream{scene} << "seed = 7\n[output]\nframes = 8\nfps = 24\nwidth = 160\nheight = 90\n"
                          "quality = \"preview\"\n[camera]\nposition = [0, 1.6, -5]\n"
                          "look_at = [0, 0, 3]\nfov_deg = 60\n[rain]\nrate_mm_per_h = 30\n"
                          "far_m = 2.5\n[splashes]\nenabled = true\n"
                          "[environment]\nname = \"night_street\"\n";
  const auto out = (dir / "out").string();
  const auto alone = run_raintrace(
      {"render", scene.string(), "-o", out, "--frames", "5", "--no-movie"}, dir / "log_alone");
  ASSERT_EQ(alone.exit_code, 0) << alone.output;
  const std::string frame_alone = frame_file(dir / "out", 5);
  const auto range = run_raintrace(
      {"render", scene.string(), "-o", out, "--frames", "3-6", "--no-movie"}, dir / "log_range");
  EXPECT_EQ(range.exit_code, 0) << range.output;
  EXPECT_TRUE(frame_file(dir / "out", 5) == frame_alone)
      << "frame 5 was exported anew as other text";
  EXPECT_NE(range.output.find("3 frames rendered, 1 up to date, 0 failed"), std::string::npos)
      << range.output;
}

// `--width/--height` are the scene's [output] size given on the command line: the simulation's
// camera takes its aspect and its pixels from them (the view it fills with rain, how fine the
// rain, the splashes and the ripples are drawn). Until 2026-12-04 the overrides reached the
// picture alone, so a 16:9 scene rendered at 4:3 was simulated for a 16:9 view, with the
// scene file's pixels, under the same scene hash as the scene file that says 4:3.
TEST_F(PovrayRenderCli, TheSizeOnTheCommandLineMakesTheFramesOfThatSizeInTheSceneFile) {
  const auto dir = testing::fresh_test_dir("cli_size_override");
  const auto wide = write_scene(dir, 1, "wide.toml");  // 64×36
  std::string text = read_all(wide);
  const auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  replace("width = 64", "width = 128");
  replace("height = 36", "height = 96");
  const auto narrow = dir / "narrow.toml";
  std::ofstream{narrow} << text;
  const auto overridden = run_raintrace({"render", wide.string(), "-o", (dir / "a").string(),
                                         "--width", "128", "--height", "96", "--no-movie"},
                                        dir / "log_a");
  ASSERT_EQ(overridden.exit_code, 0) << overridden.output;
  const auto written =
      run_raintrace({"export", narrow.string(), "-o", (dir / "b").string()}, dir / "log_b");
  ASSERT_EQ(written.exit_code, 0) << written.output;
  const std::string expected = frame_file(dir / "b", 1);
  EXPECT_FALSE(expected.empty());
  // The frame's text names its ripple map by a hash of its pixels, so equal text is an equal map.
  EXPECT_TRUE(frame_file(dir / "a", 1) == expected) << "the overridden size simulated another view";
  EXPECT_EQ(read_all(dir / "a/scene.inc"), read_all(dir / "b/scene.inc"));
  EXPECT_TRUE(image_is_complete(dir / "a" / final_image_name(Pass::image, 1), 128, 96));
}

TEST_F(PovrayRenderCli, SigkillWhileExportingAndRenderingThenRerunRedoesOnlyUnfinishedFrames) {
  const auto dir = testing::fresh_test_dir("cli_kill_scene");
  const int frames = 16;
  const auto scene = write_scene(dir, frames);
  const auto plain =
      run_raintrace({"export", scene.string(), "-o", (dir / "plain").string()}, dir / "log_plain");
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  const std::vector<std::string> args{
      "render", scene.string(), "-o", (dir / "out").string(), "--jobs", "1", "--no-movie"};
  ChildProcess child{raintrace_spec(args, dir / "log")};
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (rendered_in_manifest(dir / "out") < 2 && std::chrono::steady_clock::now() < deadline &&
         !child.poll()) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_FALSE(child.poll().has_value()) << read_all(dir / "log");
  ::kill(child.pid(), SIGKILL);
  EXPECT_EQ(child.wait(), 128 + SIGKILL);

  // Every frame file at its final name is complete (byte-identical to a plain export's).
  for (int f = 1; f <= frames; ++f) {
    if (std::filesystem::exists(dir / "out" / fmt::format("frames/frame_{:04d}.pov", f))) {
      EXPECT_EQ(frame_file(dir / "out", f), frame_file(dir / "plain", f)) << "frame " << f;
    }
  }
  const Finished finished = finished_images(dir / "out");
  ASSERT_GE(finished.exr.size(), 2U);
  ASSERT_LT(finished.exr.size(), static_cast<std::size_t>(frames));

  const auto r = run_raintrace(args, dir / "log2");
  expect_rerun_redid_only_unfinished(r, dir / "out", finished, frames);
  for (int f = 1; f <= frames; ++f) {
    EXPECT_EQ(frame_file(dir / "out", f), frame_file(dir / "plain", f)) << "frame " << f;
  }
}

}  // namespace
}  // namespace raintrace::render
