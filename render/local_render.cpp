// Local backend: planning from the manifest (or from frames as the exporter publishes them),
// the runner, and manifest updates per frame.
#include "render/local_render.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "povgen/manifest.h"
#include "render/environment_plate.h"
#include "render/frame_plan.h"
#include "render/process.h"

namespace raintrace::render {
namespace {

// manifest.json as this run keeps it: in memory, sorted by frame number, written after every
// change so a killed run loses nothing it finished.
class ManifestBook {
 public:
  explicit ManifestBook(std::filesystem::path path)
      : m_path{std::move(path)}, m_manifest{povgen::read_manifest(m_path)} {
    std::sort(m_manifest.frames.begin(), m_manifest.frames.end(),
              [](const auto& a, const auto& b) { return a.number < b.number; });
  }

  [[nodiscard]] const povgen::Manifest& manifest() const { return m_manifest; }

  /// The entry of frame `number`; throws std::out_of_range when the manifest has none.
  povgen::FrameEntry& at(int number) {
    const auto it = lower_bound(number);
    if (it == m_manifest.frames.end() || it->number != number) {
      throw std::out_of_range("manifest has no frame " + std::to_string(number));
    }
    return *it;
  }

  /// Inserts the entry or replaces the one with its number.
  void put(povgen::FrameEntry entry) {
    const auto it = lower_bound(entry.number);
    if (it != m_manifest.frames.end() && it->number == entry.number) {
      *it = std::move(entry);
    } else {
      m_manifest.frames.insert(it, std::move(entry));
    }
  }

  void save() const { povgen::write_manifest(m_path, m_manifest); }

 private:
  std::vector<povgen::FrameEntry>::iterator lower_bound(int number) {
    return std::lower_bound(m_manifest.frames.begin(), m_manifest.frames.end(), number,
                            [](const auto& f, int n) { return f.number < n; });
  }

  std::filesystem::path m_path;
  povgen::Manifest m_manifest;
};

bool mask_needed(const povgen::FrameEntry& f, const std::filesystem::path& out_dir, int digits,
                 bool force, bool image_stale) {
  return force || image_stale ||
         !std::filesystem::exists(out_dir / final_image_name(Pass::mask, f.number, digits));
}

// Jobs for frames as the exporter publishes them: each frame that needs a render waits until
// its span is complete (StreamingSpans), images before masks.
class FeedSource : public JobSource {
 public:
  FeedSource(FrameFeed& feed, ManifestBook& book, const std::filesystem::path& out_dir,
             const LocalRenderSettings& settings, int digits, int jobs, RenderProgress& progress)
      : m_feed{feed},
        m_book{book},
        m_out{out_dir},
        m_settings{settings},
        m_digits{digits},
        m_jobs{jobs},
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

  /// Records what the exporter published since the last call in the manifest and the plan.
  void pull() {
    auto batch = m_feed.take();
    for (auto& entry : batch.frames) {
      const bool stale = frame_needs_render(entry, m_out, m_settings.force);
      const bool mask =
          m_settings.mask && mask_needed(entry, m_out, m_digits, m_settings.force, stale);
      m_images.arrived(entry.number, stale);
      m_masks.arrived(entry.number, mask);
      m_jobs_known += (stale ? 1 : 0) + (mask ? 1 : 0);
      m_progress.skipped += stale ? 0 : 1;
      ++m_progress.exported;
      m_book.put(std::move(entry));
    }
    if (batch.closed) {
      m_images.close(m_jobs);
      m_masks.close(m_jobs);
      m_closed = true;
    }
    if (!batch.frames.empty()) m_book.save();
    update_total();
  }

  [[nodiscard]] bool feed_closed() const { return m_closed; }

 private:
  void update_total() {
    const int passes = m_settings.mask ? 2 : 1;
    const int unexported =
        m_closed ? 0 : std::max(0, m_progress.export_total - m_progress.exported);
    m_progress.total = m_jobs_known + passes * unexported;
  }

  FrameFeed& m_feed;
  ManifestBook& m_book;
  std::filesystem::path m_out;
  const LocalRenderSettings& m_settings;
  int m_digits;
  int m_jobs;
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

void require_povray() {
  if (!find_program("povray")) {
    throw std::runtime_error("POV-Ray not found: install it with `sudo apt-get install povray`");
  }
}

void clean_temp_images(const std::filesystem::path& out_dir) {
  std::filesystem::remove_all(out_dir / temp_dir_name());
}

RenderSummary render_local(const std::filesystem::path& out_dir,
                           const LocalRenderSettings& settings) {
  require_povray();
  ManifestBook book{out_dir / "manifest.json"};
  clean_temp_images(out_dir);
  const int digits =
      settings.incoming != nullptr ? settings.incoming->digits() : frame_digits(book.manifest());
  const int jobs = std::max(1, settings.jobs);

  RenderSummary summary;
  auto& progress = summary.progress;
  const auto start = std::chrono::steady_clock::now();
  auto report = [&] {
    progress.elapsed_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const int finished = progress.done + progress.failed;
    progress.eta_seconds =
        finished > 0 ? progress.elapsed_seconds / finished * (progress.total - finished) : -1.0;
    if (settings.on_progress) settings.on_progress(progress);
  };

  RunnerSettings runner;
  runner.jobs = jobs;
  runner.width = book.manifest().width;
  runner.height = book.manifest().height;
  runner.digits = digits;
  runner.stop = settings.stop;
  RunnerCallbacks callbacks;
  callbacks.on_rendered = [&](Pass pass, int frame, double seconds) {
    ++progress.done;
    if (pass == Pass::image) {
      auto& entry = book.at(frame);
      entry.status = "rendered";
      entry.rendered_hash = entry.input_hash;
      entry.render_seconds = seconds;
      entry.error.clear();
      book.save();
    }
    report();
  };
  callbacks.on_failed = [&](const FrameFailure& failure) {
    ++progress.failed;
    summary.failures.push_back(failure);
    if (failure.pass == Pass::image) {
      auto& entry = book.at(failure.frame);
      entry.status = "failed";
      entry.rendered_hash.clear();
      entry.error = failure.summary();
      book.save();
    }
    if (settings.on_failed) settings.on_failed(failure);
    report();
  };
  callbacks.on_tick = report;

  auto report_plate = [&](const EnvironmentPlate& plate) {
    if (!plate.problem().empty() && !plate.interrupted() && settings.on_notice) {
      settings.on_notice(environment_plate_notice(plate));
    }
  };

  if (settings.incoming != nullptr) {
    // Started before anything is known about the frames: it renders while the exporter
    // simulates. (A run whose frames all turn out up to date renders it anyway.)
    EnvironmentPlate plate{out_dir, runner.width, runner.height, settings.stop};
    FeedSource feed{*settings.incoming, book, out_dir, settings, digits, jobs, progress};
    AfterPlate source{feed, plate, [&] { report_plate(plate); }};
    report();
    summary.interrupted = !run_povray_jobs(out_dir, source, runner, callbacks);
    plate.wait();  // only still running when stopped: this ends it
    // Stopped early: the exporter stops too (same flag) after its current frame. Record every
    // frame it finished, so the manifest matches the frame files on disk.
    while (!feed.feed_closed()) {
      feed.pull();
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    report();
    return summary;
  }

  const povgen::Manifest& manifest = book.manifest();
  const std::vector<int> frames =
      frames_needing_render(manifest, out_dir, settings.force, settings.only);
  std::vector<int> masks;
  if (settings.mask) {
    for (const auto& f : manifest.frames) {
      if (settings.only && (f.number < settings.only->first || f.number > settings.only->last)) {
        continue;
      }
      const bool stale = std::binary_search(frames.begin(), frames.end(), f.number);
      if (mask_needed(f, out_dir, digits, settings.force, stale)) masks.push_back(f.number);
    }
  }

  std::deque<RenderJob> queue;
  for (const auto& span : split_into_spans(frames, jobs, settings.max_span)) {
    queue.push_back({Pass::image, span});
  }
  for (const auto& span : split_into_spans(masks, jobs, settings.max_span)) {
    queue.push_back({Pass::mask, span});
  }

  progress.total = static_cast<int>(frames.size() + masks.size());
  progress.skipped = static_cast<int>(manifest.frames.size()) - static_cast<int>(frames.size());
  if (settings.only) {
    progress.skipped = 0;
    for (const auto& f : manifest.frames) {
      if (f.number >= settings.only->first && f.number <= settings.only->last) ++progress.skipped;
    }
    progress.skipped -= static_cast<int>(frames.size());
  }
  report();
  if (!queue.empty()) {
    EnvironmentPlate plate{out_dir, runner.width, runner.height, settings.stop};
    plate.wait(report);  // keeps the progress display alive
    if (plate.interrupted()) {
      summary.interrupted = true;
      return summary;
    }
    report_plate(plate);
  }
  summary.interrupted = !run_povray_jobs(out_dir, std::move(queue), runner, callbacks);
  report();
  return summary;
}

}  // namespace raintrace::render
