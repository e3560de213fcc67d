// The scheduler. One rule keeps it safe: an image reaches its final name only after it decodes
// completely at the expected size, so a killed POV-Ray (or raintrace) never leaves a final-
// looking image that is half written. Files in the temp folders carry no meaning across runs.
#include "render/povray_runner.h"

#include <fmt/core.h>
#include <chrono>
#include <memory>
#include <thread>
#include <vector>

#include "output/disk_space.h"
#include "output/image_check.h"
#include "render/process.h"
#include "render/text_file.h"

namespace raintrace::render {
namespace {

using Clock = std::chrono::steady_clock;

struct Running {
  RenderJob job;
  int attempt = 1;  // how many times POV-Ray was started on this span's first frame
  std::unique_ptr<ChildProcess> process;
  std::vector<std::string> argv;
  std::string log;               // relative to out_dir
  int next_frame = 0;            // first frame of the span not yet promoted
  Clock::time_point since;       // start of next_frame's work (process start or last promotion)
  Clock::time_point share_read;  // when its log was last read for the share traced
};

// The rest of a span, to run again ahead of new work.
struct Retry {
  RenderJob job;
  int attempt = 1;
};

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// A fixed list of jobs, all ready from the start.
class QueueSource : public JobSource {
 public:
  explicit QueueSource(std::deque<RenderJob> jobs) : m_jobs{std::move(jobs)} {}
  std::optional<RenderJob> next() override {
    if (m_jobs.empty()) return std::nullopt;
    RenderJob job = m_jobs.front();
    m_jobs.pop_front();
    return job;
  }
  [[nodiscard]] bool exhausted() const override { return m_jobs.empty(); }

 private:
  std::deque<RenderJob> m_jobs;
};

class Runner {
 public:
  Runner(const std::filesystem::path& out_dir, const RunnerSettings& settings,
         const RunnerCallbacks& callbacks)
      : m_out{out_dir}, m_settings{settings}, m_callbacks{callbacks} {}

  bool run(JobSource& source) {
    std::filesystem::create_directories(m_out / "logs");
    prepare_povray_home(m_out);
    std::vector<Running> running;
    // Spans whose every image is promoted. POV-Ray idles ~0.4 s after its last image before it
    // exits; that time no longer holds a job slot, and at the very end it is cut short.
    std::vector<Running> draining;
    std::deque<Retry> retries;  // failed spans' frames, ahead of new work
    while (!retries.empty() || !running.empty() || !source.exhausted()) {
      if (stop_requested()) {
        for (auto& r : running) {
          r.process->stop();
          promote_ready(r);
        }
        for (auto& d : draining) d.process->stop();
        return false;
      }
      while (static_cast<int>(running.size()) < std::max(1, m_settings.jobs)) {
        Retry next;
        if (!retries.empty()) {
          next = retries.front();
          retries.pop_front();
        } else if (const std::optional<RenderJob> job = source.next()) {
          next.job = *job;
        } else {
          break;
        }
        running.push_back(start(next.job, next.attempt));
      }
      bool any_ended = false;
      for (auto it = running.begin(); it != running.end();) {
        promote_ready(*it);
        report_traced_share(*it);
        if (const auto code = it->process->poll()) {
          finish(*it, *code, retries);
          it = running.erase(it);
          any_ended = true;
        } else if (it->next_frame > it->job.span.last) {
          draining.push_back(std::move(*it));
          it = running.erase(it);
          any_ended = true;
        } else {
          ++it;
        }
      }
      std::erase_if(draining, [](Running& d) { return d.process->poll().has_value(); });
      if (m_callbacks.on_tick) m_callbacks.on_tick();
      if (!any_ended) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    // Every image is in place and verified, so nothing these processes still do matters: end
    // them now (POV-Ray takes ~0.3 s to act on SIGTERM) instead of waiting for their exit.
    for (auto& d : draining) d.process->stop(0.0);
    return !stop_requested();
  }

 private:
  bool stop_requested() const { return m_settings.stop != nullptr && m_settings.stop->load(); }

  // Room one more frame needs at most: an uncompressed half-float RGBA EXR (8 bytes a pixel),
  // its developed 8-bit PNG (3), plus its log: 64 KiB and, for each 32×32 block, a progress line
  // (+V) of ~40 bytes, 48 allowed.
  [[nodiscard]] std::uint64_t image_bytes() const {
    const auto pixels = static_cast<std::uint64_t>(m_settings.width) * m_settings.height;
    return pixels * 11 + (pixels / 1024 + 1) * 48 + 65536;
  }

  Running start(const RenderJob& job, int attempt) {
    if (m_callbacks.on_started) m_callbacks.on_started(job);
    Running r;
    r.job = job;
    r.attempt = attempt;
    r.argv = povray_argv(job.pass, job.span, m_settings.digits);
    r.log = fmt::format("logs/{}_{:04d}-{:04d}.log", job.pass == Pass::image ? "image" : "mask",
                        job.span.first, job.span.last);
    r.next_frame = job.span.first;
    std::filesystem::create_directories(m_out / temp_dir_name());
    // A leftover temp image of a frame about to render must never be mistaken for new output.
    for (int f = job.span.first; f <= job.span.last; ++f) {
      std::filesystem::remove(m_out / temp_image_name(job.pass, f, m_settings.digits));
    }
    ProcessSpec spec;
    spec.argv = r.argv;
    spec.working_dir = m_out;
    spec.env = povray_env(m_out);
    spec.log_path = m_out / r.log;
    r.since = Clock::now();
    r.share_read = r.since;
    r.process = std::make_unique<ChildProcess>(spec);
    return r;
  }

  // Promotes consecutive finished frames from next_frame on. POV-Ray writes a frame's image in
  // one go after tracing it, so "decodes completely" means "finished".
  void promote_ready(Running& r) {
    while (r.next_frame <= r.job.span.last) {
      const auto temp = m_out / temp_image_name(r.job.pass, r.next_frame, m_settings.digits);
      if (!output::image_is_complete(temp, m_settings.width, m_settings.height)) return;
      const auto final_path = m_out / final_image_name(r.job.pass, r.next_frame, m_settings.digits);
      std::filesystem::create_directories(final_path.parent_path());
      if (r.job.pass == Pass::image) {
        // The PNG developed from the EXR being replaced goes first: no PNG ever stands beside
        // an EXR it was not developed from.
        std::filesystem::remove(m_out / developed_image_name(r.next_frame, m_settings.digits));
      }
      std::filesystem::rename(temp, final_path);
      const double seconds = seconds_since(r.since);
      r.since = Clock::now();
      if (m_callbacks.on_rendered) m_callbacks.on_rendered(r.job.pass, r.next_frame, seconds);
      ++r.next_frame;
    }
  }

  // POV-Ray's progress for the frame it traces, read from its log's end once a second. The
  // last "Rendered N of M pixels" is the frame after the last promoted one: a whole frame's
  // (1) is left out, and the next frame prints none while it parses.
  void report_traced_share(Running& r) {
    if (!m_callbacks.on_traced_share || r.next_frame > r.job.span.last) return;
    if (seconds_since(r.share_read) < 1.0) return;
    r.share_read = Clock::now();
    const std::optional<double> share = povray_traced_share(read_tail(m_out / r.log, 256));
    if (share && *share < 1.0) m_callbacks.on_traced_share(r.job.pass, r.next_frame, *share);
  }

  void finish(Running& r, int exit_code, std::deque<Retry>& queue) {
    promote_ready(r);
    if (r.next_frame > r.job.span.last) return;
    if (stop_requested()) return;  // interrupted, not failed: the next run redoes the rest
    const std::string log_text = read_text(m_out / r.log);
    // POV-Ray gave up before reading the scene (a loaded machine): the same frames again.
    const bool did_not_start = povray_did_not_start(log_text);
    if (did_not_start && r.attempt < kPovrayStartAttempts) {
      queue.push_front({{r.job.pass, {r.next_frame, r.job.span.last}}, r.attempt + 1});
      return;
    }
    // POV-Ray says "Cannot access data in file" when its image does not fit: ask the disk.
    output::throw_if_out_of_space(
        m_out, image_bytes(),
        fmt::format("POV-Ray could not write {} of frame {} into {} (log {})",
                    r.job.pass == Pass::image ? "the image" : "the mask", r.next_frame,
                    m_out.string(), r.log));
    FrameFailure failure;
    failure.frame = r.next_frame;
    failure.pass = r.job.pass;
    failure.command =
        "cd " + shell_quote_command({m_out.string()}) + " && HOME=. " + shell_quote_command(r.argv);
    failure.exit_code = exit_code;
    failure.log = r.log;
    failure.error_lines = povray_error_lines(log_text);
    if (did_not_start) {
      failure.error_lines.push_back(povray_did_not_start_line(r.attempt));
    }
    if (failure.error_lines.empty()) {
      std::string why;
      output::image_is_complete(
          m_out / temp_image_name(r.job.pass, r.next_frame, m_settings.digits), m_settings.width,
          m_settings.height, &why);
      failure.error_lines.push_back(
          fmt::format("{}: {}", temp_image_name(r.job.pass, r.next_frame, m_settings.digits), why));
    }
    if (m_callbacks.on_failed) m_callbacks.on_failed(failure);
    // The frames after the failed one were never reached: they get their own process, ahead of
    // the queue so the frame order stays roughly sequential.
    if (r.next_frame < r.job.span.last) {
      queue.push_front({{r.job.pass, {r.next_frame + 1, r.job.span.last}}});
    }
  }

  std::filesystem::path m_out;
  RunnerSettings m_settings;
  RunnerCallbacks m_callbacks;
};

}  // namespace

std::string FrameFailure::summary() const {
  std::string out;
  for (const auto& line : error_lines) {
    if (!out.empty()) out += " | ";
    out += line;
  }
  return out;
}

bool run_povray_jobs(const std::filesystem::path& out_dir, std::deque<RenderJob> jobs,
                     const RunnerSettings& settings, const RunnerCallbacks& callbacks) {
  QueueSource source{std::move(jobs)};
  return Runner{out_dir, settings, callbacks}.run(source);
}

bool run_povray_jobs(const std::filesystem::path& out_dir, JobSource& source,
                     const RunnerSettings& settings, const RunnerCallbacks& callbacks) {
  return Runner{out_dir, settings, callbacks}.run(source);
}

}  // namespace raintrace::render
