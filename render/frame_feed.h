// Frames that arrive while the local renderer runs: the exporter publishes each frame once its
// files are in place (renamed, never half-written), and the renderer picks them up between
// POV-Ray polls, so the first frames are ray-traced while later ones are still being simulated.
// Thread-safe for one producer and one consumer.
#pragma once

#include <mutex>
#include <vector>

#include "output/export.h"

namespace raintrace::render {

class FrameFeed {
 public:
  /// expected_frames: how many frames the producer means to publish (progress, ETA and span
  /// lengths are planned from it), >= 0.
  explicit FrameFeed(int expected_frames) : m_expected{expected_frames} {}
  FrameFeed(const FrameFeed&) = delete;
  FrameFeed& operator=(const FrameFeed&) = delete;

  /// Producer: this frame's .pov (and mask .pov) are complete at their final names, with the
  /// input_hash of what POV-Ray will read. Frames come in ascending order; a frame number
  /// published twice is a programming error (ignored).
  void publish(output::ExportedFrame frame);
  /// Producer: nothing more will come (all frames published, or the producer stopped early).
  /// Idempotent.
  void close();

  struct Batch {
    std::vector<output::ExportedFrame> frames;  ///< published since the previous take, ascending
    bool closed = false;                        ///< true: no frame will follow these
  };
  /// Consumer: takes what was published since the last call, without waiting.
  Batch take();

  [[nodiscard]] int expected_frames() const { return m_expected; }

 private:
  const int m_expected;
  std::mutex m_mutex;
  std::vector<output::ExportedFrame> m_ready;
  int m_last_number = 0;
  bool m_closed = false;
};

}  // namespace raintrace::render
