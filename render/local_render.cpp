// Local backend: a thin executor of the folder's plan (or of frames as the exporter publishes
// them). Deciding what is due and recording results are the folder state's job.
#include "render/local_render.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "render/environment_plate.h"
#include "render/process.h"
#include "render/spans.h"

namespace raintrace::render {
namespace {

using output::FolderState;
using output::RenderReason;

// Jobs for frames as the exporter publishes them: each picture that needs a render waits until
// its span is complete (StreamingSpans), images before masks. A frame whose EXR is current but
// whose PNG is not goes straight to develop.
class FeedSource : public JobSource {
 public:
  FeedSource(FrameFeed& feed, FolderState& folder, const LocalRenderSettings& settings, int jobs,
             RenderProgress& progress, std::function<void(int, bool)> develop)
      : m_feed{feed},
        m_folder{folder},
        m_settings{settings},
        m_develop{std::move(develop)},
        m_jobs{jobs},
        m_masks_wanted{folder.manifest().identity.masks},
        m_progress{progress},
        m_images{streaming_span_length(feed.expected_frames(), jobs, settings.max_span)},
        m_masks{streaming_span_length(feed.expected_frames(), jobs, settings.max_span)} {
    m_progress.export_total = feed.expected_frames();
    update_total();
  }

  std::optional<RenderJob> next() override {
    pull();
    if (auto span = m_images.take_ready()) return RenderJob{Pass::image, *span};
    if (auto span = m_masks.take_ready()) return RenderJob{Pass::mask, *span};
    return std::nullopt;
  }

  [[nodiscard]] bool exhausted() const override {
    return m_images.exhausted() && m_masks.exhausted();
  }

  /// Records what the exporter published since the last call in the folder and the plan.
  void pull() {
    auto batch = m_feed.take();
    for (const auto& frame : batch.frames) {
      m_folder.frame_exported(frame.number, frame.input_hash);
      const bool image =
          output::needs_render(m_folder.decide(Pass::image, frame.number, m_settings.force));
      const bool mask = m_masks_wanted && output::needs_render(m_folder.decide(
                                              Pass::mask, frame.number, m_settings.force));
      const bool develop_only =
          !image && output::needs_develop(m_folder.decide_develop(frame.number));
      m_images.arrived(frame.number, image);
      m_masks.arrived(frame.number, mask);
      if (develop_only) m_develop(frame.number, true);
      m_jobs_known += (image || develop_only ? 1 : 0) + (mask ? 1 : 0);
      m_progress.skipped += image || develop_only || mask ? 0 : 1;
      ++m_progress.exported;
    }
    if (batch.closed) {
      m_images.close(m_jobs);
      m_masks.close(m_jobs);
      m_closed = true;
    }
    if (!batch.frames.empty()) m_folder.save();
    update_total();
  }

  [[nodiscard]] bool feed_closed() const { return m_closed; }

 private:
  void update_total() {
    const int passes = m_masks_wanted ? 2 : 1;
    const int unexported =
        m_closed ? 0 : std::max(0, m_progress.export_total - m_progress.exported);
    m_progress.total = m_jobs_known + passes * unexported;
  }

  FrameFeed& m_feed;
  FolderState& m_folder;
  const LocalRenderSettings& m_settings;
  std::function<void(int, bool)> m_develop;
  int m_jobs;
  bool m_masks_wanted;
  RenderProgress& m_progress;
  StreamingSpans m_images;
  StreamingSpans m_masks;
  int m_jobs_known = 0;  // images and masks known to need a render
  bool m_closed = false;
};

// Holds the frames back until the environment plate is finished, so every frame sees the same
// plate (or none). Meanwhile the feed is still drained, so the manifest and progress keep up
// with the exporter.
class AfterPlate : public JobSource {
 public:
  AfterPlate(FeedSource& source, EnvironmentPlate& plate, std::function<void()> on_plate_done)
      : m_source{source}, m_plate{plate}, m_on_plate_done{std::move(on_plate_done)} {}

  std::optional<RenderJob> next() override {
    if (!m_plate_done) {
      if (!m_plate.poll()) {
        m_source.pull();
        return std::nullopt;
      }
      m_plate_done = true;
      m_on_plate_done();
    }
    return m_source.next();
  }

  [[nodiscard]] bool exhausted() const override { return m_plate_done && m_source.exhausted(); }

 private:
  FeedSource& m_source;
  EnvironmentPlate& m_plate;
  std::function<void()> m_on_plate_done;
  bool m_plate_done = false;
};

}  // namespace

RenderSummary render_local(FolderState& folder, const LocalRenderSettings& settings) {
  require_povray();
  const auto display = prepare_develop(folder);
  const auto& out_dir = folder.dir();
  clean_temp_images(out_dir);
  const int jobs = std::max(1, settings.jobs);
  const auto& identity = folder.manifest().identity;

  RenderSummary summary;
  ProgressReporter reporter{settings.on_progress};
  reporter.follow_pace();
  auto& progress = reporter.progress();
  RunnerSettings runner;
  runner.jobs = jobs;
  runner.width = identity.width;
  runner.height = identity.height;
  runner.digits = folder.digits();
  runner.stop = settings.stop;
  DevelopQueue developer{out_dir, develop_target(folder.manifest()), *display, settings.stop};
  auto develop = [&developer](int frame, bool only = false) { developer.submit(frame, only); };
  RunnerCallbacks callbacks =
      folder_callbacks(folder, reporter, summary, settings.on_failed, develop);
  callbacks.on_tick = [&] {
    record_developed(folder, reporter, summary, developer.take(), settings.on_failed);
    reporter.report();
  };
  auto notice = [&](const std::string& text) {
    if (settings.on_notice) settings.on_notice(text);
  };
  auto report_plate = [&](const EnvironmentPlate& plate) {
    if (!plate.problem().empty() && !plate.interrupted()) notice(environment_plate_notice(plate));
  };
  auto finish = [&] {
    // Every frame POV-Ray finished is developed before the run ends (when stopped, only the
    // frame in hand: the others stay rendered, and the next run develops them).
    finish_developing(developer, folder, reporter, summary, settings.on_failed);
    if (settings.stop != nullptr && settings.stop->load()) summary.interrupted = true;
    reporter.report();
    summary.progress = progress;
    return summary;
  };

  if (settings.incoming != nullptr) {
    // Started before anything is known about the frames: it renders while the exporter
    // simulates. (A run whose frames all turn out up to date renders it anyway.)
    EnvironmentPlate plate{out_dir, runner.width, runner.height, settings.stop};
    FeedSource feed{*settings.incoming, folder, settings, jobs, progress, develop};
    AfterPlate source{feed, plate, [&] { report_plate(plate); }};
    reporter.report();
    summary.interrupted = !run_povray_jobs(out_dir, source, runner, callbacks);
    plate.wait();  // only still running when stopped: this ends it
    // Stopped early: the exporter stops too (same flag) after its current frame. Record every
    // frame it finished, so the manifest matches the frame files on disk.
    while (!feed.feed_closed()) {
      feed.pull();
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return finish();
  }

  const output::RenderPlan plan = folder.plan({settings.force, settings.only});
  if (settings.on_plan) settings.on_plan(plan);
  std::deque<RenderJob> queue;
  for (const auto& span : split_into_spans(plan.images, jobs, settings.max_span)) {
    queue.push_back({Pass::image, span});
  }
  for (const auto& span : split_into_spans(plan.masks, jobs, settings.max_span)) {
    queue.push_back({Pass::mask, span});
  }
  progress.total = static_cast<int>(plan.images.size() + plan.masks.size() + plan.develops.size());
  progress.skipped = plan.up_to_date;
  for (const int frame : plan.develops) developer.submit(frame, true);
  reporter.report();
  if (!queue.empty()) {
    EnvironmentPlate plate{out_dir, runner.width, runner.height, settings.stop};
    plate.wait(callbacks.on_tick);  // keeps the progress display (and develop) going
    if (plate.interrupted()) {
      summary.interrupted = true;
      return finish();
    }
    report_plate(plate);
  }
  summary.interrupted = !run_povray_jobs(out_dir, std::move(queue), runner, callbacks);
  return finish();
}

}  // namespace raintrace::render
