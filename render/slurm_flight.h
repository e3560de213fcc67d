// What each Slurm array task has in flight, published for the submitting raintrace's ETA.
//
// A local render's ETA follows the pace of its POV-Ray processes (render_pace.h): when each
// starts a span of frames, and how much of its frame POV-Ray has traced. Before this, a Slurm
// render's ETA was the rate of finished pictures, which knows nothing until the first frames
// finish (95–130 s at 1280×720 final, longer for larger frames) and then rises between
// bursts, as the local one did. So each task publishes the same two things in a small file of
// its own, OUT/slurm/results/.flight_T.json (the leading dot keeps it out of the result
// merging), rewritten atomically as they change, about once a second while POV-Ray traces. The
// submitting raintrace reads them at each poll and tells its ProgressReporter, whose pace then
// works as a local render's.
//
// RenderPace treats the pictures in flight as sharing one machine: a picture's cost is its
// share, dt / n. n tasks on n nodes are such a machine while the cluster keeps n running, which
// share_frames' nearly equal shares make true until the last frames. A task that waits in the
// queue publishes nothing, and its frames count as queued at the pace of those running.
//
// Usage:
//   in the task:       publish_flight(results, task, run_id, {Pass::image, {1, 8}, 3, 0.4});
//                      retire_flight(results, task);           // the task is done
//   in the submitter:  FlightFollower flights;
//                      flights.follow(results, run_id, reporter);  // after merging results
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "render/progress.h"

namespace raintrace::render {

/// One task's POV-Ray process: the span it was started on, the frame it traces now, and the
/// share of that frame's pixels traced (negative until POV-Ray has said).
struct TaskFlight {
  Pass pass = Pass::image;
  FrameSpan span;
  int frame = 0;
  double share = -1.0;
};

/// Writes task `task`'s flight into `results` (atomically), tagged with the run's id.
void publish_flight(const std::filesystem::path& results, int task, const std::string& run_id,
                    const TaskFlight& flight);
/// Removes task `task`'s flight file: it has nothing more in flight.
void retire_flight(const std::filesystem::path& results, int task);

/// Follows the tasks' flight files for one run and tells a ProgressReporter what they show.
class FlightFollower {
 public:
  /// Reads every flight file in `results` written for `run_id`: a process not seen before is
  /// started at the frame it traces now (frames it finished before were not in flight here),
  /// and its traced share is passed on. Call after merging the result files, so a finished
  /// frame leaves the flight before the next one's share arrives. Files it cannot read are
  /// skipped: the ETA is a guide, the results are what count.
  void follow(const std::filesystem::path& results, const std::string& run_id,
              ProgressReporter& reporter);

 private:
  std::map<int, TaskFlight> m_seen;  ///< by task: its process as last read
};

}  // namespace raintrace::render
