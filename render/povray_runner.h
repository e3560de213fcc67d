// Runs POV-Ray over spans of frames with several processes in flight, verifies and promotes
// each finished image (temp name → final name), and reports per frame. The same engine serves
// the local backend (many spans, N jobs) and a Slurm task (its own spans, one job).
#pragma once

#include <atomic>
#include <deque>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "render/povray_command.h"

namespace raintrace::render {

struct RenderJob {
  Pass pass = Pass::image;
  FrameSpan span;
};

/// A frame POV-Ray did not produce.
struct FrameFailure {
  int frame = 0;
  Pass pass = Pass::image;
  std::string command;                   ///< the POV-Ray command line, with its working directory
  int exit_code = 0;                     ///< POV-Ray's exit code (128 + signal when killed)
  std::vector<std::string> error_lines;  ///< POV-Ray's own error lines from the log
  std::string log;                       ///< the log file, relative to the output folder
  /// POV-Ray made the EXR, but developing it into the PNG failed (error_lines says why;
  /// command, exit_code and log are empty).
  bool in_develop = false;
  /// One line: the error lines joined, or why the image was rejected.
  std::string summary() const;
};

struct RunnerCallbacks {
  /// POV-Ray is about to start on this job (also on the rest of a failed span). May throw to
  /// stop the run: running processes are then stopped and nothing further is promoted.
  std::function<void(const RenderJob& job)> on_started;
  /// A verified image is now at final_image_name(pass, frame).
  std::function<void(Pass pass, int frame, double seconds)> on_rendered;
  std::function<void(const FrameFailure&)> on_failed;
  /// About once a second for each process in flight: the share of its current frame's pixels
  /// POV-Ray has traced, from its log (povray_traced_share), while under 1.
  std::function<void(Pass pass, int frame, double share)> on_traced_share;
  /// Called about every 100 ms while waiting, for progress displays.
  std::function<void()> on_tick;
};

struct RunnerSettings {
  int jobs = 2;   ///< POV-Ray processes in flight, >= 1
  int width = 0;  ///< expected image size (from the manifest)
  int height = 0;
  int digits = 4;  ///< digits in frame numbers of file names (frame_digits(manifest))
  /// Set from a signal handler: children are stopped, finished images kept.
  const std::atomic<bool>* stop = nullptr;
};

/// Where the runner gets work when it streams (the local backend while frames are exported).
class JobSource {
 public:
  virtual ~JobSource() = default;
  /// The next job that can start now, or nullopt when none is ready yet. Asked whenever a
  /// process slot is free, about every 50 ms.
  virtual std::optional<RenderJob> next() = 0;
  /// True once next() will never return a job again.
  [[nodiscard]] virtual bool exhausted() const = 0;
};

/// Renders every job; returns false when stopped by settings.stop (finished frames are promoted
/// and reported first). A span whose process fails at frame f reports f and goes on with
/// f+1..last in a new process — unless the folder's filesystem is full: then it throws
/// std::system_error (ENOSPC) naming the frame, since every further frame would fail the same
/// way — or POV-Ray did not start: then the same frames run again, up to kPovrayStartAttempts
/// starts in all. Logs go to out_dir/logs/<pass>_AAAA-BBBB.log (each start rewrites its log).
bool run_povray_jobs(const std::filesystem::path& out_dir, std::deque<RenderJob> jobs,
                     const RunnerSettings& settings, const RunnerCallbacks& callbacks);
/// The same, with jobs taken from `source` as they become ready, until it is exhausted and
/// every process has ended. The rest of a failed span is retried before new jobs.
bool run_povray_jobs(const std::filesystem::path& out_dir, JobSource& source,
                     const RunnerSettings& settings, const RunnerCallbacks& callbacks);

}  // namespace raintrace::render
