// Slurm backend: planning helpers (always), and a real job array on a one-node cluster that must
// produce the same pixels as the local backend (label slurm).
#include "render/slurm_render.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>
#include <unistd.h>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>

#include "output/folder_state.h"
#include "output/image_check.h"
#include "render/environment_plate.h"
#include "render/local_render.h"
#include "render/process.h"
#include "render/test_folder.h"

namespace raintrace::render {
namespace {

using output::image_is_complete;

/// Opens the folder as `raintrace render DIR --backend slurm` does and renders it.
RenderSummary render_slurm(const std::filesystem::path& dir, const SlurmRenderSettings& s) {
  auto folder = output::FolderState::open(dir, "test");
  return render::render_slurm(folder, s);
}

RenderSummary render_local(const std::filesystem::path& dir, const LocalRenderSettings& s) {
  auto folder = output::FolderState::open(dir, "test");
  return render::render_local(folder, s);
}

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in{path, std::ios::binary};
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ShareFrames, SplitsIntoNearlyEqualContiguousShares) {
  // 10 frames over 4 tasks: boundaries at floor(t·10/4) = 0, 2, 5, 7, 10 → sizes 2, 3, 2, 3.
  const auto shares = share_frames({1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, 4);
  ASSERT_EQ(shares.size(), 4U);
  EXPECT_EQ(shares[0], (std::vector<int>{1, 2}));
  EXPECT_EQ(shares[1], (std::vector<int>{3, 4, 5}));
  EXPECT_EQ(shares[3], (std::vector<int>{8, 9, 10}));
  EXPECT_EQ(share_frames({4, 5}, 8).size(), 2U);  // never an empty task
}

TEST(SbatchScript, IsAnArrayRunningTheWorkerInTheOutputFolder) {
  const auto script = sbatch_script("/cluster/out", "/opt/raintrace", 6);
  EXPECT_NE(script.find("#SBATCH --array=0-5\n"), std::string::npos);
  EXPECT_NE(script.find("#SBATCH --chdir=/cluster/out\n"), std::string::npos);
  EXPECT_NE(script.find("#SBATCH --output=/cluster/out/logs/slurm_%A_%a.out\n"), std::string::npos);
  EXPECT_NE(script.find("exec '/opt/raintrace' render --slurm-task '/cluster/out'\n"),
            std::string::npos);
}

// Uses a running cluster, or (as root) starts a one-node one with the repository's own recipe,
// scripts/slurm-localhost.sh, and stops it after. That cluster is configured by SLURM_CONF,
// which sbatch and squeue, run by render_slurm(), inherit from this process.
class SlurmRender : public ::testing::Test {
 protected:
  static std::filesystem::path recipe() {
    return std::filesystem::path{RAINTRACE_SOURCE_DIR} / "scripts" / "slurm-localhost.sh";
  }
  static void SetUpTestSuite() {
    if (!find_program("sbatch") || !find_program("sinfo")) return;
    if (cluster_up()) {
      s_ready = true;
      return;
    }
    if (::geteuid() != 0) return;
    s_cluster_dir = testing::fresh_test_dir("slurm_cluster");
    ProcessSpec start;
    start.argv = {recipe().string(), "start", s_cluster_dir.string()};
    start.log_path = s_cluster_dir / "start.log";
    s_started = ChildProcess{start}.wait() == 0;
    if (s_started) ::setenv("SLURM_CONF", (s_cluster_dir / "slurm.conf").c_str(), 1);
    s_ready = s_started && cluster_up();
  }
  static void TearDownTestSuite() {
    if (!s_started) return;
    ProcessSpec stop;
    stop.argv = {recipe().string(), "stop", s_cluster_dir.string()};
    ChildProcess{stop}.wait();
    ::unsetenv("SLURM_CONF");
  }
  static bool cluster_up() {
    ProcessSpec spec;
    spec.argv = {"sinfo", "-h", "-o", "%T"};
    const auto r = run_capture(spec);
    return r.exit_code == 0 && r.out.find("idle") != std::string::npos;
  }
  void SetUp() override {
    if (!find_program("povray")) GTEST_SKIP() << "POV-Ray not installed (apt-get install povray)";
    if (!s_ready) {
      GTEST_SKIP() << "no Slurm cluster: needs sbatch/sinfo and an idle node, or root to start "
                      "one with scripts/slurm-localhost.sh";
    }
  }
  static inline bool s_ready = false;
  static inline bool s_started = false;
  static inline std::filesystem::path s_cluster_dir;
};

TEST_F(SlurmRender, JobArrayRendersTheSamePixelsAsLocal) {
  const auto dir = testing::fresh_test_dir("slurm_same");
  testing::write_test_folder(dir / "local", {.frames = 6});
  testing::write_test_folder(dir / "slurm", {.frames = 6});
  LocalRenderSettings local;
  local.jobs = 2;
  ASSERT_TRUE(render_local(dir / "local", local).failures.empty());

  SlurmRenderSettings settings;
  settings.tasks = 3;
  settings.raintrace_exe = RAINTRACE_BINARY;
  settings.poll_seconds = 0.3;
  int last_done = 0;
  settings.on_progress = [&](const RenderProgress& p) { last_done = p.done; };
  const auto summary = render_slurm(dir / "slurm", settings);
  ASSERT_TRUE(summary.failures.empty()) << summary.failures[0].summary();
  EXPECT_EQ(last_done, 6);
  const auto manifest = output::read_manifest(dir / "slurm/manifest.json");
  for (const auto& f : manifest.frames) {
    EXPECT_EQ(f.image.status, output::FrameStatus::rendered);
    EXPECT_EQ(f.image.rendered_hash, f.input_hash);
    // PNG bytes differ by timestamps (docs/povray-notes.md): compare decoded pixels exactly.
    OIIO::ImageBuf a{(dir / "local" / f.image.path).string()};
    OIIO::ImageBuf b{(dir / "slurm" / f.image.path).string()};
    const auto cmp = OIIO::ImageBufAlgo::compare(a, b, 0.0f, 0.0f);
    EXPECT_FALSE(cmp.error) << f.image.path;
    EXPECT_EQ(cmp.nfail, 0U) << f.image.path;
    EXPECT_EQ(cmp.maxerror, 0.0) << f.image.path;
    // Each task developed its own frames, byte for byte as the local run did.
    EXPECT_FALSE(f.developed.develop_hash.empty()) << f.number;
    EXPECT_EQ(f.developed.source_hash, f.image.file_hash) << f.number;
    EXPECT_TRUE(read_bytes(dir / "local" / f.developed.path) ==
                read_bytes(dir / "slurm" / f.developed.path))
        << f.developed.path;
  }
  EXPECT_EQ(summary.progress.developed_only, 0);
  int developed_on_nodes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "slurm/logs")) {
    if (entry.path().filename().string().rfind("slurm_", 0) != 0) continue;
    const std::string log = read_bytes(entry.path());
    const auto at = log.find(" frames developed here");
    if (at == std::string::npos) continue;
    developed_on_nodes += std::stoi(log.substr(log.rfind(' ', at - 1) + 1));
  }
  EXPECT_EQ(developed_on_nodes, 6);
  // A second submission finds nothing to do and submits nothing.
  EXPECT_EQ(render_slurm(dir / "slurm", settings).progress.total, 0);
}

TEST_F(SlurmRender, TheEtaIsKnownFromTheTasksProgressBeforeAFrameIsDone) {
  const auto dir = testing::fresh_test_dir("slurm_eta");
  testing::write_test_folder(dir, {.frames = 2, .width = 320, .height = 180});
  testing::replace_frame(dir, 1, testing::kSlowFrame);
  SlurmRenderSettings settings;
  settings.tasks = 1;
  settings.raintrace_exe = RAINTRACE_BINARY;
  settings.poll_seconds = 0.3;
  // The first estimate, and the picture count then: the task publishes its POV-Ray's traced
  // share (slurm_flight.h), which the submitter follows at each poll.
  testing::FirstEta first;
  settings.on_progress = std::ref(first);
  const auto summary = render_slurm(dir, settings);
  ASSERT_TRUE(summary.failures.empty()) << summary.failures[0].summary();
  EXPECT_EQ(summary.progress.done, 2);
  // From finished frames alone there is no ETA until frame 1, some 7 s of tracing, is done.
  EXPECT_GT(first.seconds, 0.0) << "no ETA while the first frame traced";
  EXPECT_EQ(first.finished_then, 0);
  EXPECT_FALSE(std::filesystem::exists(dir / "slurm/results/.flight_0.json"));
  std::printf("first ETA %.1f s, while frame 1 traced\n", first.seconds);
}

TEST_F(SlurmRender, FramesWhosePngIsAllTheyLackAreDevelopedHereWithoutAJob) {
  const auto dir = testing::fresh_test_dir("slurm_develop_here");
  testing::write_test_folder(dir / "out", {.frames = 3});
  LocalRenderSettings local;
  ASSERT_TRUE(render_local(dir / "out", local).failures.empty());
  const auto png = dir / "out" / developed_image_name(2);
  const std::string bytes = read_bytes(png);
  std::filesystem::remove(png);
  SlurmRenderSettings settings;
  settings.raintrace_exe = RAINTRACE_BINARY;
  bool submitted = false;
  settings.on_status = [&](const std::string& s) { submitted |= s.rfind("submitted", 0) == 0; };
  const auto summary = render_slurm(dir / "out", settings);
  EXPECT_TRUE(summary.failures.empty());
  EXPECT_FALSE(submitted);
  EXPECT_EQ(summary.progress.developed_only, 1);
  EXPECT_TRUE(read_bytes(png) == bytes);
}

TEST_F(SlurmRender, EnvironmentPlateIsFinishedBeforeTheArrayIsSubmitted) {
  const auto dir = testing::fresh_test_dir("slurm_plate");
  testing::write_test_folder(dir / "out", {.frames = 2, .plate = true});
  SlurmRenderSettings settings;
  settings.tasks = 2;
  settings.raintrace_exe = RAINTRACE_BINARY;
  settings.poll_seconds = 0.3;
  std::vector<std::string> statuses;
  bool plate_before_submission = false;
  settings.on_status = [&](const std::string& s) {
    statuses.push_back(s);
    if (s.rfind("submitted", 0) == 0) {
      plate_before_submission = image_is_complete(dir / "out" / kPlateImage, 64, 36);
    }
  };
  const auto summary = render_slurm(dir / "out", settings);
  EXPECT_TRUE(summary.failures.empty());
  EXPECT_EQ(summary.progress.done, 2);
  EXPECT_TRUE(plate_before_submission);
  for (const auto& s : statuses) EXPECT_EQ(s.find("environment plate"), std::string::npos) << s;
  EXPECT_TRUE(image_is_complete(dir / "out/images/frame_0002.exr", 64, 36));
  EXPECT_TRUE(image_is_complete(dir / "out/images/frame_0002.png", 64, 36));
}

TEST_F(SlurmRender, AFailingFrameIsReportedFromItsTask) {
  const auto dir = testing::fresh_test_dir("slurm_fail");
  testing::write_test_folder(dir / "out", {.frames = 4});
  testing::replace_frame(dir / "out", 2, "#include \"scene.inc\"\nsphere { <0,0,0> oops }\n");
  SlurmRenderSettings settings;
  settings.tasks = 2;
  settings.raintrace_exe = RAINTRACE_BINARY;
  settings.poll_seconds = 0.3;
  const auto summary = render_slurm(dir / "out", settings);
  ASSERT_EQ(summary.failures.size(), 1U);
  EXPECT_EQ(summary.failures[0].frame, 2);
  EXPECT_EQ(summary.failures[0].error_lines.at(0).rfind("File 'frames/frame_0002.pov' line 2", 0),
            0U);
  EXPECT_EQ(summary.progress.done, 3);
  EXPECT_EQ(output::read_manifest(dir / "out/manifest.json").frames[1].image.status,
            output::FrameStatus::failed);
}

}  // namespace
}  // namespace raintrace::render
