// The output folder as a user meets it, end to end through the `raintrace` program: two runs on
// one folder, another scene, a shorter scene, a folder raintrace did not make, images damaged
// between runs, Ctrl-C in the middle of a long prewarm, develop-only edits, a folder rendered
// by hand, and a develop killed halfway. Each case ends with the folder equal
// to a clean render of the same scene (frame files byte for byte, images pixel for pixel).
#include <gtest/gtest.h>
#include <unistd.h>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <thread>

#include <OpenImageIO/imageio.h>

#include <map>

#include "output/image_check.h"
#include "output/manifest.h"
#include "render/povray_command.h"
#include "render/process.h"
#include "render/test_folder.h"
#include "tests/cli_test_support.h"

namespace raintrace::render {
namespace {

namespace fs = std::filesystem;
using clitest::expect_same_as_clean_render;
using clitest::raintrace_spec;
using clitest::read_all;
using clitest::run_raintrace;
using clitest::write_scene;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// Renders `scene` into a fresh folder `clean` (the reference for a test's final state).
void clean_render(const fs::path& scene, const fs::path& clean,
                  std::vector<std::string> extra = {}) {
  std::vector<std::string> args{"render", scene.string(), "-o", clean.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const auto r = run_raintrace(args, clean.string() + ".log");
  ASSERT_EQ(r.exit_code, 0) << r.output;
}

/// Waits until the log of a running raintrace holds `text` (or it ends, or 60 s pass).
bool wait_for_log(ChildProcess& child, const fs::path& log, const std::string& text) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!contains(read_all(log), text)) {
    if (child.poll() || std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return true;
}

class PovrayFolderCli : public testing::PovrayTest {};

TEST_F(PovrayFolderCli, ASecondRunOnTheSameFolderStopsAtOnceNamingTheFirst) {
  const auto dir = testing::fresh_test_dir("cli_two_runs");
  testing::write_test_folder(dir / "out", {.frames = 8, .spheres = 6000});
  ChildProcess first{
      raintrace_spec({"render", (dir / "out").string(), "--jobs", "1"}, dir / "first.log")};
  ASSERT_TRUE(wait_for_log(first, dir / "first.log", "frames done")) << read_all(dir / "first.log");
  const auto start = std::chrono::steady_clock::now();
  const auto second = run_raintrace({"render", (dir / "out").string()}, dir / "second.log");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(second.exit_code, 4) << second.output;  // cli/exit_codes.h: busy
  EXPECT_TRUE(contains(second.output, (dir / "out").string() + " is in use by another raintrace"))
      << second.output;
  EXPECT_TRUE(contains(second.output, "pid " + std::to_string(first.pid()))) << second.output;
  EXPECT_TRUE(contains(second.output, "raintrace render " + (dir / "out").string()))
      << second.output;
  EXPECT_LT(seconds, 5.0) << "the second run waited instead of failing at once";
  // An export into it is refused the same way, before it looks at the folder.
  const auto scene = write_scene(dir, 2);
  const auto exporting =
      run_raintrace({"export", scene.string(), "-o", (dir / "out").string()}, dir / "export.log");
  EXPECT_EQ(exporting.exit_code, 4) << exporting.output;

  EXPECT_EQ(first.wait(), 0) << read_all(dir / "first.log");
  testing::write_test_folder(dir / "clean", {.frames = 8, .spheres = 6000});
  ASSERT_EQ(run_raintrace({"render", (dir / "clean").string()}, dir / "clean.log").exit_code, 0);
  expect_same_as_clean_render(dir / "out", dir / "clean");
}

TEST_F(PovrayFolderCli, AnotherSceneIsRefusedAndForceReplacesItWithACleanRender) {
  const auto dir = testing::fresh_test_dir("cli_other_scene");
  const auto light = write_scene(dir, 4, "light.toml", 7);
  // Another scene: other rain (the seed alone would be "this scene with other settings").
  const auto other = write_scene(dir, 4, "other.toml", 7, "[export]\nsphere_distance_m = 1\n");
  ASSERT_EQ(run_raintrace({"render", light.string(), "-o", (dir / "out").string()}, dir / "a.log")
                .exit_code,
            0);
  const auto refused = run_raintrace(
      {"render", other.string(), "-o", (dir / "out").string(), "--frames", "1-2"}, dir / "b.log");
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_TRUE(contains(refused.output, "holds 4 frames of another scene")) << refused.output;
  EXPECT_TRUE(contains(refused.output, "Use --force")) << refused.output;
  // Untouched: the first scene is still complete and up to date.
  const auto again =
      run_raintrace({"render", light.string(), "-o", (dir / "out").string()}, dir / "c.log");
  EXPECT_TRUE(contains(again.output, "0 frames rendered, 4 up to date")) << again.output;

  const auto forced = run_raintrace(
      {"render", other.string(), "-o", (dir / "out").string(), "--frames", "1-2", "--force"},
      dir / "d.log");
  EXPECT_EQ(forced.exit_code, 0) << forced.output;
  EXPECT_TRUE(contains(forced.output, "replaced 4 frames of another scene")) << forced.output;
  clean_render(other, dir / "clean", {"--frames", "1-2"});
  expect_same_as_clean_render(dir / "out", dir / "clean");
  // `render OUT` now calls the other scene's frames up to date, and only those.
  const auto folder = run_raintrace({"render", (dir / "out").string()}, dir / "e.log");
  EXPECT_TRUE(contains(folder.output, "0 frames rendered, 2 up to date")) << folder.output;
}

TEST_F(PovrayFolderCli, AShorterSceneLeavesNoFrameOfTheLongerOne) {
  const auto dir = testing::fresh_test_dir("cli_shorter");
  const auto longer = write_scene(dir, 6, "scene.toml");
  ASSERT_EQ(run_raintrace({"render", longer.string(), "-o", (dir / "out").string()}, dir / "a.log")
                .exit_code,
            0);
  // Only [output] frames differs: the same scene (a frame does not depend on the frames after
  // it), so no --force is needed.
  const auto shorter = write_scene(dir / "short", 3, "scene.toml");
  const auto r =
      run_raintrace({"render", shorter.string(), "-o", (dir / "out").string()}, dir / "b.log");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  clean_render(shorter, dir / "clean");
  expect_same_as_clean_render(dir / "out", dir / "clean");
  EXPECT_FALSE(fs::exists(dir / "out" / final_image_name(Pass::image, 4)));
  EXPECT_FALSE(fs::exists(dir / "out/frames/frame_0006.pov"));
}

TEST_F(PovrayFolderCli, AFolderRaintraceDidNotMakeIsRefusedAndForceKeepsTheUsersFiles) {
  const auto dir = testing::fresh_test_dir("cli_foreign");
  fs::create_directories(dir / "out/images");
  std::ofstream{dir / "out/notes.txt"} << "my notes";
  std::ofstream{dir / "out/images/holiday.jpg"} << "not a render";
  const auto scene = write_scene(dir, 3);
  const auto refused =
      run_raintrace({"render", scene.string(), "-o", (dir / "out").string()}, dir / "a.log");
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_TRUE(contains(refused.output, "is not empty and raintrace did not make it"))
      << refused.output;
  EXPECT_FALSE(fs::exists(dir / "out/manifest.json"));
  const auto forced = run_raintrace(
      {"render", scene.string(), "-o", (dir / "out").string(), "--force"}, dir / "b.log");
  EXPECT_EQ(forced.exit_code, 0) << forced.output;
  EXPECT_EQ(read_all(dir / "out/notes.txt"), "my notes");
  EXPECT_EQ(read_all(dir / "out/images/holiday.jpg"), "not a render");
  clean_render(scene, dir / "clean");
  expect_same_as_clean_render(dir / "out", dir / "clean");
}

TEST_F(PovrayFolderCli, MissingTruncatedEmptyAndChangedImagesAreRenderedAgain) {
  const auto dir = testing::fresh_test_dir("cli_damaged");
  const auto scene = write_scene(dir, 5);
  const std::vector<std::string> args{"render", scene.string(), "-o", (dir / "out").string()};
  ASSERT_EQ(run_raintrace(args, dir / "a.log").exit_code, 0);
  const auto image = [&](int n) { return dir / "out" / final_image_name(Pass::image, n); };
  fs::remove(image(1));
  fs::resize_file(image(2), fs::file_size(image(2)) / 2);
  fs::resize_file(image(3), 0);
  fs::copy_file(image(5), image(4), fs::copy_options::overwrite_existing);  // a valid PNG
  const auto r = run_raintrace(args, dir / "b.log");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "4 frames rendered, 1 up to date")) << r.output;
  // The same damage through `render OUT`, which says why it renders what it renders.
  fs::resize_file(image(2), 0);
  fs::resize_file(image(3), fs::file_size(image(3)) - 100);
  fs::copy_file(image(5), image(1), fs::copy_options::overwrite_existing);
  const auto folder = run_raintrace({"render", (dir / "out").string()}, dir / "c.log");
  EXPECT_EQ(folder.exit_code, 0) << folder.output;
  EXPECT_TRUE(contains(folder.output,
                       "3 to render: 1 image empty, 1 image truncated, 1 image "
                       "changed; 2 frames up to date"))
      << folder.output;
  clean_render(scene, dir / "clean");
  expect_same_as_clean_render(dir / "out", dir / "clean");
}

TEST_F(PovrayFolderCli, CtrlCInALongPrewarmStopsWithinASecondAndTheRunResumes) {
  const auto dir = testing::fresh_test_dir("cli_prewarm");
  // 200 000 substeps of prewarm (20 s of simulated time at 0.1 ms) over a few hundred drops:
  // seconds of work before the first frame, where the simulation used to ignore SIGINT.
  const auto scene = dir / "prewarm.toml";
  std::ofstream{scene} << "seed = 7\n[output]\nframes = 2\nwidth = 64\nheight = 36\n"
                          "[simulation]\nprewarm_s = 20\nsubstep_s = 0.0001\n"
                          "[rain]\nrate_mm_per_h = 2\nfar_m = 1.2\n";
  const std::vector<std::string> args{"render", scene.string(), "-o", (dir / "out").string()};
  for (const int sig : {SIGINT, SIGTERM}) {
    const auto log = dir / (std::string{"stopped_"} + std::to_string(sig) + ".log");
    ChildProcess child{raintrace_spec(args, log)};
    // The first progress line comes once the render side is set up (loading the colour
    // configuration takes ~0.35 s, seconds under ASan on a busy machine, and is not
    // interruptible): from then on the run waits on nothing but the prewarm.
    ASSERT_TRUE(wait_for_log(child, log, "render: 0/2 frames done")) << read_all(log);
    std::this_thread::sleep_for(std::chrono::milliseconds(500));  // well inside the prewarm
    ASSERT_FALSE(child.poll()) << read_all(log);
    const auto start = std::chrono::steady_clock::now();
    ::kill(child.pid(), sig);
    const int code = child.wait();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(code, 128 + sig) << read_all(log);
    // The requirement is one second; the margin is for a machine busy with other builds. Under
    // AddressSanitizer the whole run is four to five times slower (this test 55–73 s against
    // 15 s) and the exit ends in LeakSanitizer's scan, and 2.0057 s was once measured on a busy
    // machine: a sanitized build checks that the stop is prompt, the normal build the second.
#if defined(__SANITIZE_ADDRESS__)
    constexpr double kStopLimitSeconds = 4.0;
#else
    constexpr double kStopLimitSeconds = 2.0;
#endif
    EXPECT_LT(seconds, kStopLimitSeconds) << "stopping took " << seconds << " s";
    EXPECT_TRUE(contains(read_all(log), "run the same command again to resume")) << read_all(log);
  }
  const auto resumed = run_raintrace(args, dir / "resumed.log");
  EXPECT_EQ(resumed.exit_code, 0) << resumed.output;
  clean_render(scene, dir / "clean");
  expect_same_as_clean_render(dir / "out", dir / "clean");
}

TEST_F(PovrayFolderCli, AScenePastTheMemoryOrWorkLimitStopsBeforeItWritesAnything) {
  const auto dir = testing::fresh_test_dir("cli_limits");
  const auto scene = write_scene(dir, 3);
  const std::vector<std::string> args{"render", scene.string(), "-o", (dir / "out").string()};
  auto with = [&](std::vector<std::string> extra) {
    auto all = args;
    all.insert(all.end(), extra.begin(), extra.end());
    return all;
  };
  const auto memory = run_raintrace(with({"--max-memory", "64M"}), dir / "a.log");
  EXPECT_EQ(memory.exit_code, 2) << memory.output;
  EXPECT_TRUE(contains(memory.output, "this scene needs about")) << memory.output;
  EXPECT_TRUE(contains(memory.output, "lower [rain] far_m or rate_mm_per_h")) << memory.output;
  EXPECT_TRUE(contains(memory.output, "raise the limit with --max-memory 1G")) << memory.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
  const auto work = run_raintrace(with({"--max-drop-steps", "1000"}), dir / "b.log");
  EXPECT_EQ(work.exit_code, 2) << work.output;
  EXPECT_TRUE(contains(work.output, "drop-steps of simulation")) << work.output;
  EXPECT_TRUE(contains(work.output, "--max-drop-steps")) << work.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
  // The limit raised as the message says: the run goes through.
  const auto raised = run_raintrace(with({"--max-memory", "1G"}), dir / "c.log");
  EXPECT_EQ(raised.exit_code, 0) << raised.output;
  clean_render(scene, dir / "clean");
  expect_same_as_clean_render(dir / "out", dir / "clean");
}

// Bytes a folder takes on a tmpfs: every file rounded up to whole 4 KiB pages, and a page per
// folder.
std::uintmax_t tmpfs_usage(const fs::path& dir) {
  std::uintmax_t bytes = 4096;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    bytes += entry.is_regular_file() ? (entry.file_size() + 4095) / 4096 * 4096 : 4096;
  }
  return bytes;
}

int run_tool(const std::vector<std::string>& argv) {
  ProcessSpec spec;
  spec.argv = argv;
  return run_capture(spec).exit_code;
}

TEST_F(PovrayFolderCli, AFullDiskStopsTheRunNamingTheCauseAndTheRunResumesWhenThereIsRoom) {
  if (::geteuid() != 0) {
    GTEST_SKIP() << "needs root to mount a small tmpfs (mount -t tmpfs -o size=…): skipped";
  }
  const auto dir = testing::fresh_test_dir("cli_disk_full");
  const auto scene = write_scene(dir, 4);
  clean_render(scene, dir / "clean");
  const auto usage = tmpfs_usage(dir / "clean");
  const auto mnt = dir / "mnt";
  fs::create_directories(mnt);
  struct Unmount {
    fs::path path;
    ~Unmount() { run_tool({"umount", path.string()}); }
  };
  // The disk fills at a different stage each time: export, the plate, frames, the movie.
  for (const double share : {0.3, 0.6, 0.85}) {
    const auto size =
        std::to_string(static_cast<std::uintmax_t>(share * static_cast<double>(usage)) / 1024) +
        "k";
    if (run_tool({"mount", "-t", "tmpfs", "-o", "size=" + size, "tmpfs", mnt.string()}) != 0) {
      GTEST_SKIP() << "mount -t tmpfs failed (not allowed here?): skipped";
    }
    const Unmount unmount{mnt};
    const auto r = run_raintrace({"render", scene.string(), "-o", (mnt / "out").string()},
                                 dir / ("full_" + size + ".log"));
    EXPECT_EQ(r.exit_code, 3) << "tmpfs of " << size << ":\n" << r.output;  // system error
    EXPECT_TRUE(contains(r.output, "No space left on device")) << r.output;
    // Room again: the same command finishes what the full disk stopped.
    ASSERT_EQ(run_tool({"mount", "-o", "remount,size=" + std::to_string(usage * 4 / 1024) + "k",
                        mnt.string()}),
              0);
    const auto resumed = run_raintrace({"render", scene.string(), "-o", (mnt / "out").string()},
                                       dir / ("resumed_" + size + ".log"));
    EXPECT_EQ(resumed.exit_code, 0) << resumed.output;
    expect_same_as_clean_render(mnt / "out", dir / "clean");
  }
}

/// `scene` with lines inserted right after its "[camera]" line.
fs::path with_camera_keys(const fs::path& scene, const fs::path& out, const std::string& keys) {
  std::string text = read_all(scene);
  const auto at = text.find("[camera]\n");
  EXPECT_NE(at, std::string::npos);
  text.insert(at + 9, keys);
  std::ofstream{out} << "# the same rain, developed otherwise\n" << text;
  return out;
}

/// The develop settings a developed PNG's description names.
std::string description_of(const fs::path& png) {
  auto in = OIIO::ImageInput::open(png.string());
  return in ? in->spec().get_string_attribute("ImageDescription") : "";
}

TEST_F(PovrayFolderCli, DevelopOnlyEditsDevelopEveryFrameAgainWithoutRenderingOrForce) {
  const auto dir = testing::fresh_test_dir("cli_develop_only");
  const auto scene = write_scene(dir, 4);
  const std::string out = (dir / "out").string();
  ASSERT_EQ(run_raintrace({"render", scene.string(), "-o", out}, dir / "a.log").exit_code, 0);
  std::map<int, fs::file_time_type> exr_written;
  for (int n = 1; n <= 4; ++n) {
    exr_written[n] = fs::last_write_time(dir / "out" / final_image_name(Pass::image, n));
  }
  // A comment and four develop keys: the rendered frames stay, every PNG is developed again.
  const auto darker =
      with_camera_keys(scene, dir / "darker.toml",
                       "exposure_ev = -1\nlook = \"high-contrast\"\nbloom = 0.1\nvignette = 0\n");
  const auto r = run_raintrace({"render", darker.string(), "-o", out}, dir / "b.log");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "0 frames rendered, 4 developed only, 0 up to date")) << r.output;
  for (int n = 1; n <= 4; ++n) {
    EXPECT_EQ(fs::last_write_time(dir / "out" / final_image_name(Pass::image, n)), exr_written[n])
        << "frame " << n << " was rendered again";
    EXPECT_TRUE(contains(description_of(dir / "out" / developed_image_name(n)),
                         "exposure_ev=-1 view=filmic look=high-contrast bloom=0.1"))
        << n;
  }
  clean_render(darker, dir / "clean");
  expect_same_as_clean_render(dir / "out", dir / "clean");
  // The folder itself now develops with the new settings: nothing to do.
  const auto again = run_raintrace({"render", out}, dir / "c.log");
  EXPECT_TRUE(contains(again.output, "0 frames rendered, 4 up to date")) << again.output;
  // A damaged PNG is developed again from its EXR, never rendered.
  fs::resize_file(dir / "out" / developed_image_name(2), 100);
  fs::remove(dir / "out" / developed_image_name(3));
  const auto damaged = run_raintrace({"render", out}, dir / "d.log");
  EXPECT_TRUE(contains(damaged.output,
                       "0 to render; 2 to develop only: 1 picture missing, 1 picture changed"))
      << damaged.output;
  EXPECT_TRUE(contains(damaged.output, "0 frames rendered, 2 developed only, 2 up to date"))
      << damaged.output;
  expect_same_as_clean_render(dir / "out", dir / "clean");
}

TEST_F(PovrayFolderCli, AFolderRenderedByHandIsDevelopedNotRenderedAgain) {
  // The folder contract: `povray plate.ini` and `povray scene.ini` render it without raintrace
  // (EXRs), and `raintrace render OUT` then only develops them.
  const auto dir = testing::fresh_test_dir("cli_by_hand");
  const auto scene = write_scene(dir, 3);
  const std::string out = (dir / "out").string();
  ASSERT_EQ(run_raintrace({"export", scene.string(), "-o", out}, dir / "a.log").exit_code, 0);
  for (const char* ini : {"plate.ini", "scene.ini"}) {
    render::ProcessSpec povray;
    povray.argv = {"povray", ini, "-D"};
    povray.working_dir = dir / "out";
    povray.env = {{"HOME", out}};
    povray.log_path = dir / "povray.log";
    ASSERT_EQ(ChildProcess{povray}.wait(), 0) << ini << ": " << read_all(dir / "povray.log");
  }
  for (int n = 1; n <= 3; ++n) {
    EXPECT_TRUE(fs::exists(dir / "out" / final_image_name(Pass::image, n))) << n;
    EXPECT_FALSE(fs::exists(dir / "out" / developed_image_name(n))) << n;
  }
  const auto r = run_raintrace({"render", out}, dir / "b.log");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "0 frames rendered, 3 developed only, 0 up to date")) << r.output;
  clean_render(scene, dir / "clean");
  expect_same_as_clean_render(dir / "out", dir / "clean");
}

/// The frame's EXR at its centre: red over green.
double centre_red_over_green(const fs::path& exr) {
  auto in = OIIO::ImageInput::open(exr.string());
  if (!in) return 0.0;
  const auto& spec = in->spec();
  std::vector<float> pixels(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data())) return 0.0;
  const std::size_t at =
      (static_cast<std::size_t>(spec.height / 2) * spec.width + spec.width / 2) * spec.nchannels;
  return pixels[at] / std::max(pixels[at + 1], 1e-6f);
}

TEST_F(PovrayFolderCli, AnIncludeEditedInTheFolderIsRenderedByTheFolderAndReplacedByTheScene) {
  // The folder is plain POV-Ray: a user may change environment.inc in it and render the folder.
  // The frames rendered before the edit must not count as up to date.
  const auto dir = testing::fresh_test_dir("cli_hand_edit");
  const auto scene = write_scene(dir, 3);
  const std::string out = (dir / "out").string();
  const std::vector<std::string> from_scene{"render", scene.string(), "-o", out, "--no-movie"};
  ASSERT_EQ(run_raintrace(from_scene, dir / "a.log").exit_code, 0);
  const auto exr = dir / "out" / final_image_name(Pass::image, 2);
  EXPECT_LT(centre_red_over_green(exr), 4.0);  // the street's warm light: ~2
  // A red lamp in the middle of the view.
  std::ofstream{dir / "out" / "environment.inc", std::ios::app}
      << "sphere { <0, 1.3, -3>, 0.2 pigment { rgb <1, 0, 0> } finish { emission 4 } }\n";
  const auto edited = run_raintrace({"render", out, "--no-movie"}, dir / "b.log");
  EXPECT_EQ(edited.exit_code, 0) << edited.output;
  EXPECT_TRUE(contains(edited.output, "environment.inc edited in " + out)) << edited.output;
  EXPECT_TRUE(contains(edited.output, "3 to render: 3 inputs changed")) << edited.output;
  EXPECT_GT(centre_red_over_green(exr), 10.0);
  const auto again = run_raintrace({"render", out, "--no-movie"}, dir / "c.log");
  EXPECT_TRUE(contains(again.output, "0 frames rendered, 3 up to date")) << again.output;
  // The scene file writes its own environment.inc back, says so, and renders it.
  const auto back = run_raintrace(from_scene, dir / "d.log");
  EXPECT_EQ(back.exit_code, 0) << back.output;
  EXPECT_TRUE(contains(back.output, "environment.inc in " + out + " was edited by hand"))
      << back.output;
  EXPECT_TRUE(contains(back.output, "3 frames rendered")) << back.output;
  EXPECT_LT(centre_red_over_green(exr), 4.0);  // the street's warm light: ~2
  clean_render(scene, dir / "clean", {"--no-movie"});
  expect_same_as_clean_render(dir / "out", dir / "clean");
}

TEST_F(PovrayFolderCli, ADevelopKilledHalfwayLeavesOnlyWholePngsAndTheRunResumes) {
  const auto dir = testing::fresh_test_dir("cli_develop_killed");
  const int frames = 12;
  const auto scene = write_scene(dir, frames);
  // 640x360: each develop takes tens of milliseconds, long enough to be killed in the middle.
  const std::vector<std::string> size{"--width", "640", "--height", "360", "--no-movie"};
  auto args = [&](const fs::path& s) {
    std::vector<std::string> a{"render", s.string(), "-o", (dir / "out").string()};
    a.insert(a.end(), size.begin(), size.end());
    return a;
  };
  const auto first = run_raintrace(args(scene), dir / "a.log");
  ASSERT_EQ(first.exit_code, 0) << first.output;
  const auto brighter = with_camera_keys(scene, dir / "brighter.toml", "exposure_ev = 1\n");
  ChildProcess child{raintrace_spec(args(brighter), dir / "b.log")};
  // Killed as soon as the first PNG with the new exposure is in place.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  auto any_new = [&] {
    for (int n = 1; n <= frames; ++n) {
      if (contains(description_of(dir / "out" / developed_image_name(n)), "exposure_ev=1 ")) {
        return true;
      }
    }
    return false;
  };
  while (!any_new() && !child.poll() && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ::kill(child.pid(), SIGKILL);
  child.wait();
  // Every PNG at a final name is whole, and names the settings it was developed with; nothing
  // but EXRs and PNGs of frames is in images/ (a PNG in progress stays under images/.tmp/).
  int developed_again = 0;
  for (const auto& entry : fs::directory_iterator(dir / "out" / "images")) {
    if (entry.is_directory()) continue;
    const auto name = entry.path().filename().string();
    EXPECT_TRUE(name.rfind("frame_", 0) == 0 &&
                (entry.path().extension() == ".png" || entry.path().extension() == ".exr"))
        << name;
    EXPECT_TRUE(output::image_is_complete(entry.path(), 640, 360)) << name;
    if (entry.path().extension() == ".png") {
      developed_again += contains(description_of(entry.path()), "exposure_ev=1 ") ? 1 : 0;
    }
  }
  EXPECT_GE(developed_again, 1);
  const auto manifest = output::read_manifest(dir / "out" / "manifest.json");
  for (const auto& f : manifest.frames) {
    EXPECT_EQ(f.image.status, output::FrameStatus::rendered) << f.number;
  }
  const auto r = run_raintrace(args(brighter), dir / "c.log");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "0 frames rendered, ")) << r.output;
  const auto clean = [&] {
    std::vector<std::string> a{"render", brighter.string(), "-o", (dir / "clean").string()};
    a.insert(a.end(), size.begin(), size.end());
    return a;
  }();
  const auto clean_run = run_raintrace(clean, dir / "clean.log");
  ASSERT_EQ(clean_run.exit_code, 0) << clean_run.output;
  expect_same_as_clean_render(dir / "out", dir / "clean");
}

TEST(FolderCli, AHugeUnknownKeyIsCutInTheErrorLine) {
  const auto dir = testing::fresh_test_dir("cli_huge_key");
  std::ofstream{dir / "huge.toml"} << "[rain]\n" << std::string(15'000'000, 'x') << " = 1\n";
  const auto r = run_raintrace(
      {"export", (dir / "huge.toml").string(), "-o", (dir / "out").string()}, dir / "log");
  EXPECT_EQ(r.exit_code, 2) << r.output.substr(0, 300);
  EXPECT_LT(r.output.size(), 400U) << r.output.substr(0, 300);
  EXPECT_TRUE(contains(r.output, "rain.xxxx")) << r.output.substr(0, 300);
  EXPECT_TRUE(contains(r.output, ": unknown key")) << r.output.substr(0, 300);
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(FolderCli, AnOutputFolderThatCannotBeCreatedIsNamedWithTheReason) {
  const auto dir = testing::fresh_test_dir("cli_unwritable");
  std::ofstream{dir / "a_file"} << "not a folder";
  const auto scene = write_scene(dir, 1);
  const auto r =
      run_raintrace({"export", scene.string(), "-o", (dir / "a_file/out/x").string()}, dir / "log");
  EXPECT_EQ(r.exit_code, 3) << r.output;  // cli/exit_codes.h: system error
  EXPECT_EQ(r.output, "raintrace: error: cannot create output folder " +
                          (dir / "a_file/out/x").string() + ": Not a directory\n");
}

}  // namespace
}  // namespace raintrace::render
