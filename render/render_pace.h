// How long a render has left, from the pace of its POV-Ray processes rather than from
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
// n being how many pictures were in flight. A picture is expected to cost the mean of the last
// kRecentFinished finished ones; one in flight has that less what it has had; so
//
//     left = Σ_in flight max(mean − had, 0) + queued · mean       (seconds)
//
// The recent ones, not all: frames cost more early on. In README's first command the frames
// traced while the exporter still simulated took 1.26× the time of those after (14.9 against
// 11.8 s each), and with the mean of all of them its ETA stayed 30 % high to the end.
//
// Until a picture finishes there is no mean, and at 1280×720 final that took 95–130 s. POV-Ray
// says how much of the frame it has traced (povray_traced_share), and with its blocks taken in
// a scattered order (+RS7) that share grows with the frame's time. So once a picture in flight
// has gone from the share s₀ it first showed (with had₀ seconds) to s₁ (had₁), it is left
//
//     (1 − s₁) · (had₁ − had₀) / (s₁ − s₀)     once s₁ − s₀ ≥ kMinTracedShare,
//
// its own rate (the parse before s₀ left out), in place of max(mean − had, 0); and until a
// picture finishes, the mean is that of these pictures' whole costs (had₁ + what is left).
//
// A Slurm job's tasks are fed the same way, from the files they publish (slurm_flight.h): n
// tasks on n nodes share the cluster as n processes share a machine.
//
// Usage (render/progress.h feeds it from the runner's callbacks):
//   RenderPace pace{t0};
//   pace.started(Pass::image, {1, 3}, t0);      // a process on frames 1–3
//   pace.finished(Pass::image, 1, t1);          // frame 1 is done; frame 2 is in flight
//   pace.seconds_left(11, t1);                  // 11 pictures not yet traced
#pragma once

#include <chrono>
#include <cstddef>
#include <deque>
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
  /// POV-Ray has traced `share` (0–1) of a picture in flight's pixels by `now`. Its first
  /// report is where its rate is measured from; a share below the last one starts that again.
  void traced(Pass pass, int frame, double share, Clock::time_point now);

  /// How much more of a frame than its first report must be traced before its own rate counts.
  static constexpr double kMinTracedShare = 0.1;
  /// How many of the latest finished pictures the mean is taken over: two bursts of four
  /// processes.
  static constexpr std::size_t kRecentFinished = 8;

  /// Seconds until the `untraced` pictures not yet traced (those in flight included) are, by
  /// the formulas above; nullopt while there is no pace yet: no picture has finished and none
  /// in flight has a rate of its own.
  [[nodiscard]] std::optional<double> seconds_left(int untraced, Clock::time_point now) const;

  /// Pictures finished so far.
  [[nodiscard]] int finished_count() const { return m_finished; }

 private:
  struct InFlight {
    double had = 0.0;  ///< its share of the machine so far, seconds
    int last = 0;      ///< the last frame of its process's span
    /// Its first traced() report (share, had then) and its last; first_share < 0: none yet.
    double first_share = -1.0;
    double first_had = 0.0;
    double share = 0.0;
    double share_had = 0.0;
  };
  /// What is left of `picture` at its own rate once it has had `had` seconds (its last report's
  /// estimate less what it has had since); nullopt while it has traced under kMinTracedShare
  /// since its first report.
  [[nodiscard]] static std::optional<double> left_at_own_rate(const InFlight& picture, double had);
  /// The cost a picture is expected to have, `share` seconds of each picture in flight after
  /// the last event: the mean of the recent finished ones, or before any finishes, of those in
  /// flight with a rate of their own; nullopt while there is neither.
  [[nodiscard]] std::optional<double> mean_cost(double share) const;
  /// What each picture in flight has had by `now`, beyond what m_in_flight holds.
  [[nodiscard]] double share_since_last_event(Clock::time_point now) const;
  void advance(Clock::time_point now);

  Clock::time_point m_last_event;
  int m_finished = 0;
  std::deque<double> m_recent_costs;  ///< the last kRecentFinished finished pictures' costs
  std::map<std::pair<Pass, int>, InFlight> m_in_flight;  // by (pass, frame)
};

}  // namespace raintrace::render
