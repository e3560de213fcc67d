// How the frames a plan renders (output::FolderState::plan) are cut into POV-Ray runs, and how
// many runs are in flight. Pure, so the cutting is easy to test.
#pragma once

#include <algorithm>
#include <optional>
#include <vector>

#include "render/povray_command.h"

namespace raintrace::render {

/// Cuts ascending frame numbers into contiguous spans. Each POV-Ray start costs ~0.7 s
/// (POVRAY-NOTES), so spans are long, but short enough that `jobs` processes all get work and
/// finish together: about two spans per job, each at most max_span frames, at least 1.
std::vector<FrameSpan> split_into_spans(const std::vector<int>& frames, int jobs, int max_span);

/// Span length while frames still arrive (render_local with a FrameFeed): the length
/// split_into_spans would pick for `expected_frames`, clamped to [1, max_span].
int streaming_span_length(int expected_frames, int jobs, int max_span);

/// Frames waiting for POV-Ray while the exporter still writes later ones, in ascending order.
/// A span may start only once every frame in it exists, so the planner cuts spans from the
/// front: a run of consecutive pending frames is ready when it is `length` frames long, or when
/// it cannot grow any more (a later frame has arrived without needing a render, or nothing more
/// will arrive).
class StreamingSpans {
 public:
  explicit StreamingSpans(int length) : m_length{std::max(1, length)} {}
  /// Frame `number` has arrived (numbers ascend); `needs_render` puts it on the pending list.
  void arrived(int number, bool needs_render);
  /// Nothing more will arrive. The frames still pending are then cut into at least `jobs`
  /// spans (each at most `length`), so the processes that render the tail end together.
  void close(int jobs);
  /// Removes and returns the next span that is ready, if any.
  std::optional<FrameSpan> take_ready();
  /// True when nothing is pending and nothing more will arrive.
  [[nodiscard]] bool exhausted() const { return m_closed && m_pending.empty(); }
  [[nodiscard]] bool closed() const { return m_closed; }
  [[nodiscard]] std::size_t pending() const { return m_pending.size(); }

 private:
  int m_length;
  std::vector<int> m_pending;  // ascending
  int m_last_arrived = 0;
  bool m_closed = false;
};

/// Default number of POV-Ray processes in flight: cores/2 + 3 (4 on 2 cores). Parsing is
/// single-threaded and each process also idles ~0.24 s per frame in POV-Ray's own polling
/// loops, whatever the frame costs: the cheaper the frames, the more processes it takes to keep
/// the cores busy. With preview frames drawing the environment plate, 4 beat 3 on 2 cores at
/// every drop count (BENCHMARKS.md: 6.79 vs 6.19 frames/s at 15 k, 8.08 vs 7.10 at 2 k); for
/// expensive frames (fog, final) 4 and 3 are within the noise.
int default_jobs();

}  // namespace raintrace::render
