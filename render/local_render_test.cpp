// End-to-end renders of tiny hand-made folders with the real POV-Ray (label povray).
#include "render/local_render.h"

#include <gtest/gtest.h>
#include <atomic>
#include <chrono>
#include <fstream>
#include <functional>
#include <thread>

#include "output/folder_state.h"
#include "output/image_check.h"
#include "render/environment_plate.h"
#include "render/process.h"
#include "render/test_folder.h"
#include "render/text_file.h"

namespace raintrace::render {
namespace {

using output::image_is_complete;
using output::read_manifest;

/// Opens the folder as `raintrace render DIR` does and renders it.
RenderSummary render_local(const std::filesystem::path& dir, const LocalRenderSettings& s) {
  auto folder = output::FolderState::open(dir, "test");
  return render::render_local(folder, s);
}

LocalRenderSettings settings(int jobs, int max_span = 12, bool force = false) {
  LocalRenderSettings s;
  s.jobs = jobs;
  s.max_span = max_span;
  s.force = force;
  return s;
}

/// Every frame of the manifest in `dir` (there must be `frames`) is rendered from its current
/// input into a complete image, and nothing is left at a temp name.
void expect_every_frame_rendered(const std::filesystem::path& dir, std::size_t frames) {
  const auto manifest = read_manifest(dir / "manifest.json");
  ASSERT_EQ(manifest.frames.size(), frames);
  for (const auto& f : manifest.frames) {
    EXPECT_TRUE(image_is_complete(dir / f.image.path, 64, 36)) << f.image.path;
    EXPECT_EQ(f.image.status, output::FrameStatus::rendered);
    EXPECT_EQ(f.image.rendered_hash, f.input_hash);
    // …and developed from that very EXR into a whole PNG.
    EXPECT_TRUE(image_is_complete(dir / f.developed.path, 64, 36)) << f.developed.path;
    EXPECT_FALSE(f.developed.develop_hash.empty()) << f.number;
    EXPECT_EQ(f.developed.source_hash, f.image.file_hash) << f.number;
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir / "images/.tmp"));
}

/// Every frame's POV-Ray log says (the test folder's #debug line) whether it drew the plate.
void expect_every_frame_log_says(const std::filesystem::path& dir, const std::string& what) {
  int logs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "logs")) {
    if (entry.path().filename().string().rfind("image_", 0) != 0) continue;
    ++logs;
    EXPECT_NE(read_text(entry.path()).find(what), std::string::npos) << entry.path();
  }
  EXPECT_GT(logs, 0);
}

class PovrayLocalRender : public testing::PovrayTest {};

TEST_F(PovrayLocalRender, RendersEveryFrameToAValidImageAndRecordsItInTheManifest) {
  const auto dir = testing::fresh_test_dir("all");
  testing::write_test_folder(dir, {.frames = 6});
  const auto summary = render_local(dir, settings(2));
  EXPECT_FALSE(summary.interrupted);
  EXPECT_TRUE(summary.failures.empty());
  EXPECT_EQ(summary.progress.done, 6);
  expect_every_frame_rendered(dir, 6);
}

TEST_F(PovrayLocalRender, TheEtaIsKnownFromPovraysProgressBeforeAFrameIsDone) {
  const auto dir = testing::fresh_test_dir("eta_from_progress");
  testing::write_test_folder(dir, {.frames = 1, .width = 320, .height = 180});
  testing::replace_frame(dir, 1, testing::kSlowFrame);
  auto s = settings(1);
  // The first estimate, and the picture count then: POV-Ray's "Rendered N of M pixels" (+V),
  // read from its log once a second, gives a frame's pace while it traces.
  testing::FirstEta first;
  s.on_progress = std::ref(first);
  const auto summary = render_local(dir, s);
  EXPECT_EQ(summary.progress.done, 1);
  // With a frame's pace only from finished frames, a one-frame render has no ETA until its
  // frame is traced, and then 0 s (nothing left to trace) while it is developed.
  EXPECT_GT(first.seconds, 0.0) << "no ETA while the frame traced";
  EXPECT_EQ(first.finished_then, 0);
  std::printf("first ETA %.1f s, while the frame traced\n", first.seconds);
}

TEST_F(PovrayLocalRender, OtherDevelopSettingsDevelopEveryFrameAgainAndStartNoPovray) {
  const auto dir = testing::fresh_test_dir("develop_only");
  testing::write_test_folder(dir, {.frames = 4});
  ASSERT_EQ(render_local(dir, settings(2)).progress.done, 4);
  const auto exr_written = std::filesystem::last_write_time(dir / "images/frame_0002.exr");
  std::filesystem::remove_all(dir / "logs");
  {
    auto folder = output::FolderState::open(dir, "test");
    output::DevelopSpec darker = folder.manifest().develop;
    darker.settings.exposure_ev = -2;
    folder.set_develop(darker);
  }
  const auto summary = render_local(dir, settings(2));
  EXPECT_EQ(summary.progress.total, 4);
  EXPECT_EQ(summary.progress.done, 4);
  EXPECT_EQ(summary.progress.developed_only, 4);
  if (std::filesystem::exists(dir / "logs")) {
    for (const auto& entry : std::filesystem::directory_iterator(dir / "logs")) {
      EXPECT_NE(entry.path().filename().string().rfind("image_", 0), 0U) << "POV-Ray ran";
    }
  }
  EXPECT_EQ(std::filesystem::last_write_time(dir / "images/frame_0002.exr"), exr_written);
  expect_every_frame_rendered(dir, 4);
  EXPECT_EQ(render_local(dir, settings(2)).progress.total, 0);
}

TEST_F(PovrayLocalRender, MaskOptionAlsoRendersMaskImagesFromMaskIni) {
  const auto dir = testing::fresh_test_dir("mask");
  testing::write_test_folder(dir, {.frames = 3, .masks = true});
  auto with_masks = settings(2);
  const auto summary = render_local(dir, with_masks);
  EXPECT_TRUE(summary.failures.empty());
  EXPECT_EQ(summary.progress.done, 6);  // 3 images + 3 masks
  for (int f = 1; f <= 3; ++f) {
    EXPECT_TRUE(image_is_complete(dir / final_image_name(Pass::mask, f), 64, 36)) << f;
  }
  // Masks already there and frames unchanged: nothing to do.
  EXPECT_EQ(render_local(dir, with_masks).progress.total, 0);
}

TEST_F(PovrayLocalRender, RerunRendersOnlyFramesWhoseInputsChanged) {
  const auto dir = testing::fresh_test_dir("resume");
  testing::write_test_folder(dir, {.frames = 4});
  ASSERT_EQ(render_local(dir, settings(2)).progress.done, 4);
  const auto before = std::filesystem::last_write_time(dir / "images/frame_0001.exr");
  // Frame 3's inputs change: only it is redone.
  testing::replace_frame(dir, 3, "#include \"scene.inc\"\nsphere { 0, 1 pigment { rgb 1 } }\n");
  const auto summary = render_local(dir, settings(2));
  EXPECT_EQ(summary.progress.total, 1);
  EXPECT_EQ(summary.progress.skipped, 3);
  EXPECT_EQ(std::filesystem::last_write_time(dir / "images/frame_0001.exr"), before);
  EXPECT_EQ(render_local(dir, settings(2)).progress.total, 0);
  EXPECT_EQ(render_local(dir, settings(2, 12, true)).progress.total, 4);
}

TEST_F(PovrayLocalRender, AFrameThatFailsIsReportedWithPovrayErrorAndTheOthersFinish) {
  const auto dir = testing::fresh_test_dir("fail");
  testing::write_test_folder(dir, {.frames = 6});
  testing::replace_frame(dir, 3, "#include \"scene.inc\"\nsphere { <0,0,0> oops }\n");
  // One job, 6 frames: spans of ceil(6 / 2) = 3 → frame 3 fails at the end of span 1-3. With
  // max_span 2 the spans are 1-2, 3-4, 5-6: frame 3 fails first in its span and 4 is re-queued.
  for (int max_span : {3, 2}) {
    std::filesystem::remove_all(dir / "images");
    const auto summary = render_local(dir, settings(1, max_span, true));
    ASSERT_EQ(summary.failures.size(), 1U) << "max_span " << max_span;
    const auto& failure = summary.failures[0];
    EXPECT_EQ(failure.frame, 3);
    EXPECT_EQ(failure.exit_code, 1);  // POV-Ray exits 1 on a parse error (docs/povray-notes.md)
    ASSERT_FALSE(failure.error_lines.empty());
    EXPECT_EQ(failure.error_lines[0].rfind("File 'frames/frame_0003.pov' line 2: Parse Error", 0),
              0U)
        << failure.error_lines[0];
    EXPECT_NE(failure.command.find("povray scene.ini"), std::string::npos);
    EXPECT_EQ(summary.progress.done, 5);
    EXPECT_EQ(summary.progress.failed, 1);
    const auto manifest = read_manifest(dir / "manifest.json");
    EXPECT_EQ(manifest.frames[2].image.status, output::FrameStatus::failed);
    EXPECT_NE(manifest.frames[2].image.error.find("Parse Error"), std::string::npos);
    for (int f : {1, 2, 4, 5, 6}) {
      EXPECT_TRUE(image_is_complete(dir / final_image_name(Pass::image, f), 64, 36)) << f;
    }
    EXPECT_FALSE(std::filesystem::exists(dir / final_image_name(Pass::image, 3)));
  }
}

TEST_F(PovrayLocalRender, StopFlagKeepsFinishedFramesAndTheRerunCompletes) {
  const auto dir = testing::fresh_test_dir("stop");
  testing::write_test_folder(dir, {.frames = 8, .spheres = 3000});
  std::atomic<bool> stop{false};
  int seen = 0;
  auto stopping = settings(1, 8);
  stopping.stop = &stop;
  stopping.on_progress = [&](const RenderProgress& p) {
    seen = p.done;
    if (p.done >= 2) stop = true;
  };
  const auto first = render_local(dir, stopping);
  EXPECT_TRUE(first.interrupted);
  EXPECT_TRUE(first.failures.empty());  // an interruption is not a failure
  ASSERT_GE(seen, 2);
  ASSERT_LT(first.progress.done, 8);
  const auto second = render_local(dir, settings(2));
  EXPECT_EQ(second.progress.total, 8 - first.progress.done);
  EXPECT_EQ(second.progress.done + first.progress.done, 8);
  for (int f = 1; f <= 8; ++f) {
    EXPECT_TRUE(image_is_complete(dir / final_image_name(Pass::image, f), 64, 36)) << f;
  }
}

TEST_F(PovrayLocalRender, PlateIsRenderedBeforeTheFramesAndEveryFrameDrawsIt) {
  const auto dir = testing::fresh_test_dir("plate");
  testing::write_test_folder(dir, {.frames = 4, .plate = true});
  std::vector<std::string> notices;
  auto s = settings(2, 2);
  s.on_notice = [&](const std::string& n) { notices.push_back(n); };
  const auto summary = render_local(dir, s);
  EXPECT_TRUE(summary.failures.empty());
  EXPECT_TRUE(notices.empty());
  expect_every_frame_rendered(dir, 4);
  EXPECT_TRUE(image_is_complete(dir / kPlateImage, 64, 36));
  EXPECT_EQ(read_text(dir / kPlateSidecar), environment_plate_inputs_hash(dir) + "\n");
  expect_every_frame_log_says(dir, "raintrace: environment plate used");
}

TEST_F(PovrayLocalRender, UpToDatePlateIsNotRenderedAgainEvenWhenFramesAreForced) {
  const auto dir = testing::fresh_test_dir("plate_again");
  testing::write_test_folder(dir, {.frames = 2, .plate = true});
  ASSERT_EQ(render_local(dir, settings(2)).progress.done, 2);
  const auto plate_time = std::filesystem::last_write_time(dir / kPlateImage);
  const auto log_time = std::filesystem::last_write_time(dir / kPlateLog);
  EXPECT_EQ(render_local(dir, settings(2)).progress.total, 0);
  EXPECT_EQ(render_local(dir, settings(2, 12, true)).progress.done, 2);
  EXPECT_EQ(std::filesystem::last_write_time(dir / kPlateImage), plate_time);
  EXPECT_EQ(std::filesystem::last_write_time(dir / kPlateLog), log_time);
  expect_every_frame_log_says(dir, "raintrace: environment plate used");
}

TEST_F(PovrayLocalRender, ChangedEnvironmentRendersThePlateAgain) {
  const auto dir = testing::fresh_test_dir("plate_changed");
  testing::write_test_folder(dir, {.frames = 2, .plate = true});
  ASSERT_EQ(render_local(dir, settings(2)).progress.done, 2);
  const auto before = read_text(dir / kPlateSidecar);
  std::filesystem::remove(dir / kPlateLog);
  {
    std::ofstream out{dir / "environment.inc", std::ios::app};
    out << "sphere { <0,3,2>, 1 pigment { rgb <1,0,0> } }\n";
  }
  // The test folder's frame hashes leave out environment.inc (the exporter's include it), so
  // the frames are forced to give the run something to render.
  EXPECT_EQ(render_local(dir, settings(2, 12, true)).progress.done, 2);
  EXPECT_TRUE(std::filesystem::exists(dir / kPlateLog));
  EXPECT_TRUE(image_is_complete(dir / kPlateImage, 64, 36));
  EXPECT_NE(read_text(dir / kPlateSidecar), before);
  EXPECT_EQ(read_text(dir / kPlateSidecar), environment_plate_inputs_hash(dir) + "\n");
}

TEST_F(PovrayLocalRender, PlateThatFailsIsNoticedAndFramesRenderTheFullEnvironment) {
  const auto dir = testing::fresh_test_dir("plate_fail");
  testing::write_test_folder(dir, {.frames = 3, .plate = true});
  {
    std::ofstream out{dir / "plate.pov", std::ios::app};
    out << "sphere { <0,0,0> oops }\n";
  }
  std::vector<std::string> notices;
  auto s = settings(2);
  s.on_notice = [&](const std::string& n) { notices.push_back(n); };
  const auto summary = render_local(dir, s);
  EXPECT_TRUE(summary.failures.empty());
  expect_every_frame_rendered(dir, 3);
  ASSERT_EQ(notices.size(), 1U);
  EXPECT_NE(notices[0].find("environment plate failed"), std::string::npos) << notices[0];
  EXPECT_NE(notices[0].find("File 'plate.pov' line 6: Parse Error"), std::string::npos)
      << notices[0];
  EXPECT_NE(notices[0].find(kPlateLog), std::string::npos) << notices[0];
  EXPECT_FALSE(std::filesystem::exists(dir / kPlateImage));
  EXPECT_FALSE(std::filesystem::exists(dir / kPlateSidecar));
  expect_every_frame_log_says(dir, "raintrace: full environment");
}

TEST_F(PovrayLocalRender, StopWhileThePlateRendersStartsNoFrameAndLeavesNoPlate) {
  const auto dir = testing::fresh_test_dir("plate_stop");
  testing::write_test_folder(dir, {.frames = 2, .plate = true});
  std::atomic<bool> stop{false};
  std::vector<std::string> notices;
  auto s = settings(2);
  s.stop = &stop;
  s.on_progress = [&](const RenderProgress&) { stop = true; };
  s.on_notice = [&](const std::string& n) { notices.push_back(n); };
  const auto summary = render_local(dir, s);
  EXPECT_TRUE(summary.interrupted);
  EXPECT_TRUE(summary.failures.empty());
  EXPECT_TRUE(notices.empty());  // an interruption is not a failure
  EXPECT_EQ(summary.progress.done, 0);
  EXPECT_FALSE(std::filesystem::exists(dir / kPlateImage));
  for (const auto& entry : std::filesystem::directory_iterator(dir / "logs")) {
    EXPECT_NE(entry.path().filename().string().rfind("image_", 0), 0U) << entry.path();
  }
}

TEST_F(PovrayLocalRender, FolderWithoutPlateIniRendersNoPlate) {
  const auto dir = testing::fresh_test_dir("no_plate");
  testing::write_test_folder(dir, {.frames = 2});
  ASSERT_EQ(render_local(dir, settings(2)).progress.done, 2);
  EXPECT_FALSE(std::filesystem::exists(dir / "textures"));
  EXPECT_FALSE(std::filesystem::exists(dir / kPlateLog));
}

/// The folder's frames as the exporter would publish them.
std::vector<output::ExportedFrame> exported_frames(const std::filesystem::path& dir) {
  std::vector<output::ExportedFrame> frames;
  for (const auto& f : read_manifest(dir / "manifest.json").frames) {
    frames.push_back({f.number, f.input_hash});
  }
  return frames;
}

// The test folder's frames handed over through a FrameFeed from another thread, the way the
// exporter publishes them while it simulates: `first` frames at once, the rest once `release`
// returns true (or a generous safety deadline passes, so a broken renderer fails instead of
// hanging), then the feed closes.
class Producer {
 public:
  Producer(FrameFeed& feed, std::vector<output::ExportedFrame> entries, std::size_t first,
           std::function<bool()> release)
      : m_thread{[&feed, entries = std::move(entries), first, release = std::move(release), this] {
          for (std::size_t i = 0; i < first && i < entries.size(); ++i) feed.publish(entries[i]);
          const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
          while (!release() && std::chrono::steady_clock::now() < deadline) {
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
          }
          m_released_by_renderer = release();
          for (std::size_t i = first; i < entries.size(); ++i) feed.publish(entries[i]);
          feed.close();
        }} {}
  ~Producer() { join(); }
  Producer(const Producer&) = delete;
  Producer& operator=(const Producer&) = delete;
  void join() {
    if (m_thread.joinable()) m_thread.join();
  }
  /// True when release() said yes before the rest of the frames were published.
  bool released_by_renderer() const { return m_released_by_renderer; }

 private:
  std::atomic<bool> m_released_by_renderer{false};
  std::thread m_thread;
};

TEST_F(PovrayLocalRender, FedFramesRenderBeforeTheLastFrameIsPublished) {
  const auto dir = testing::fresh_test_dir("feed");
  testing::write_test_folder(dir, {.frames = 6});
  const auto entries = exported_frames(dir);
  FrameFeed feed{6};
  std::atomic<int> done{0};
  // Frames 4-6 are held back until a frame has rendered: a renderer that waited for the whole
  // export would never get there.
  Producer producer{feed, entries, 3, [&] { return done.load() > 0; }};
  auto fed = settings(2);  // 6 frames, 2 jobs: spans of ceil(6 / 4) = 2, so 1-2 can start
  fed.incoming = &feed;
  fed.on_progress = [&](const RenderProgress& p) { done = p.done; };
  const auto summary = render_local(dir, fed);
  producer.join();
  EXPECT_TRUE(producer.released_by_renderer());
  EXPECT_FALSE(summary.interrupted);
  EXPECT_TRUE(summary.failures.empty());
  EXPECT_EQ(summary.progress.done, 6);
  EXPECT_EQ(summary.progress.total, 6);
  EXPECT_EQ(summary.progress.exported, 6);
  EXPECT_EQ(summary.progress.export_total, 6);
  expect_every_frame_rendered(dir, 6);
}

TEST_F(PovrayLocalRender, FedFramesWaitForThePlateWhileTheFeedIsStillRead) {
  const auto dir = testing::fresh_test_dir("feed_plate");
  testing::write_test_folder(dir, {.frames = 4, .plate = true});
  FrameFeed feed{4};
  std::atomic<int> exported{0};
  // The rest is published only once the renderer has recorded the first two, which it must do
  // while the plate still renders (no frame can have started before it).
  Producer producer{feed, exported_frames(dir), 2, [&] { return exported.load() >= 2; }};
  auto fed = settings(2);
  fed.incoming = &feed;
  fed.on_progress = [&](const RenderProgress& p) { exported = p.exported; };
  const auto summary = render_local(dir, fed);
  producer.join();
  EXPECT_TRUE(producer.released_by_renderer());
  EXPECT_TRUE(summary.failures.empty());
  expect_every_frame_rendered(dir, 4);
  EXPECT_TRUE(image_is_complete(dir / kPlateImage, 64, 36));
  expect_every_frame_log_says(dir, "raintrace: environment plate used");
}

TEST_F(PovrayLocalRender, FedFramesThatAreUpToDateAreSkippedAndMasksFollow) {
  const auto dir = testing::fresh_test_dir("feed_skip");
  testing::write_test_folder(dir, {.frames = 4, .masks = true});
  ASSERT_EQ(render_local(dir, settings(2)).progress.done, 8);
  testing::replace_frame(dir, 3, "#include \"scene.inc\"\nsphere { 0, 1 pigment { rgb 1 } }\n");
  std::filesystem::remove(dir / final_image_name(Pass::mask, 1));
  std::filesystem::resize_file(dir / final_image_name(Pass::mask, 2), 0);
  FrameFeed feed{4};
  Producer producer{feed, exported_frames(dir), 4, [] { return true; }};
  auto fed = settings(2);
  fed.incoming = &feed;
  int most_total = 0;
  fed.on_progress = [&](const RenderProgress& p) { most_total = std::max(most_total, p.total); };
  const auto summary = render_local(dir, fed);
  // Frame 3 changed: its image and mask; masks 1 (missing) and 2 (emptied) again; frame 4 is
  // up to date.
  EXPECT_EQ(summary.progress.done, 4);
  EXPECT_EQ(summary.progress.total, 4);
  EXPECT_EQ(summary.progress.skipped, 1);
  EXPECT_LE(most_total, 8);  // never more than 4 frames × (image + mask)
  for (int f = 1; f <= 4; ++f) {
    EXPECT_TRUE(image_is_complete(dir / final_image_name(Pass::mask, f), 64, 36)) << f;
  }
}

TEST_F(PovrayLocalRender, StopWhileFedStillRecordsEveryPublishedFrameInTheManifest) {
  const auto dir = testing::fresh_test_dir("feed_stop");
  testing::write_test_folder(dir, {.frames = 4});
  auto entries = exported_frames(dir);
  // Frames 3 and 4 arrive only after the stop, as from an exporter finishing its current frame.
  entries[2].input_hash = "after-stop-3";
  entries[3].input_hash = "after-stop-4";
  FrameFeed feed{4};
  std::atomic<bool> stop{false};
  Producer producer{feed, entries, 2, [&] { return stop.load(); }};
  auto fed = settings(1, 2);
  fed.incoming = &feed;
  fed.stop = &stop;
  fed.on_progress = [&](const RenderProgress& p) {
    if (p.done >= 1) stop = true;
  };
  const auto summary = render_local(dir, fed);
  EXPECT_TRUE(summary.interrupted);
  EXPECT_TRUE(summary.failures.empty());
  const auto manifest = read_manifest(dir / "manifest.json");
  ASSERT_EQ(manifest.frames.size(), 4U);
  EXPECT_EQ(manifest.frames[0].image.status, output::FrameStatus::rendered);
  EXPECT_EQ(manifest.frames[2].input_hash, "after-stop-3");
  EXPECT_EQ(manifest.frames[3].input_hash, "after-stop-4");
  EXPECT_NE(manifest.frames[3].image.status, output::FrameStatus::rendered);
}

}  // namespace
}  // namespace raintrace::render
