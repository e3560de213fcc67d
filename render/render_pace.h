// How long a local render has left, from the pace of its POV-Ray processes rather than from
// the pictures finished so far. Several processes start together and finish together, so the
// plain rate (elapsed ÷ finished × left) is off by the depth of that pipeline: rendering the
// default example's frames 1–12 at 1280×720 final with 4 processes on 2 cores, the first
// picture came after 96 s of a 303 s render and the plain rate said 1055 s were left where 207
// were; between batches it grew by a second each second (BENCHMARKS.md, "The render's ETA from
// its processes' pace").
//
// Each POV-Ray process runs as many threads as there are cores, so the processes in flight
// share the machine evenly, and it does a second's work each second whether one process runs
// or four. A picture's cost is its share of the machine while it ran: the integral of dt / n,
// n being how many pictures were in flight. A picture is expected to cost the mean of the
// finished ones; one in flight has that less what it has had; so
//
//     left = Σ_in flight max(mean − had, 0) + queued · mean       (seconds)
//
// Usage (render/progress.h feeds it from the runner's callbacks):
//   RenderPace pace{t0};
//   pace.started(Pass::image, {1, 3}, t0);      // a process on frames 1–3
//   pace.finished(Pass::image, 1, t1);          // frame 1 is done; frame 2 is in flight
//   pace.seconds_left(11, t1);                  // 11 pictures not yet traced
#pragma once

#include <chrono>
#include <map>
#include <optional>
#include <utility>

#include "output/layout.h"

namespace raintrace::render {

using output::FrameSpan;
using output::Pass;

class RenderPace {
 public:
  using Clock = std::chrono::steady_clock;

  explicit RenderPace(Clock::time_point start = Clock::now()) : m_last_event{start} {}

  /// A process started on `span` of `pass` at `now`: its first frame is in flight.
  void started(Pass pass, const FrameSpan& span, Clock::time_point now);
  /// A picture finished at `now`; the next frame of its process's span, if any, is in flight.
  /// A picture that was not in flight is ignored.
  void finished(Pass pass, int frame, Clock::time_point now);
  /// A picture failed at `now`: it leaves the flight and its cost is not counted (the runner
  /// starts the rest of its span anew, which started() records).
  void failed(Pass pass, int frame, Clock::time_point now);

  /// Seconds until the `untraced` pictures not yet traced (those in flight included) are, by
  /// the formula above; nullopt until a picture has finished, since there is no pace yet.
  [[nodiscard]] std::optional<double> seconds_left(int untraced, Clock::time_point now) const;

  /// Pictures finished so far.
  [[nodiscard]] int finished_count() const { return m_finished; }

 private:
  struct InFlight {
    double had = 0.0;  ///< its share of the machine so far, seconds
    int last = 0;      ///< the last frame of its process's span
  };
  /// What each picture in flight has had by `now`, beyond what m_in_flight holds.
  [[nodiscard]] double share_since_last_event(Clock::time_point now) const;
  void advance(Clock::time_point now);

  Clock::time_point m_last_event;
  int m_finished = 0;
  double m_finished_cost = 0.0;
  std::map<std::pair<Pass, int>, InFlight> m_in_flight;  // by (pass, frame)
};

}  // namespace raintrace::render
