// Frames that arrive while the local renderer runs: the exporter publishes each frame once its
// files are in place (renamed, never half-written), and the renderer picks them up between
// POV-Ray polls, so the first frames are ray-traced while later ones are still being simulated.
// Thread-safe for one producer and one consumer.
#pragma once

#include <mutex>
#include <vector>

#include "povgen/manifest.h"

namespace raintrace::render {

class FrameFeed {
 public:
  /// expected_frames: how many frames the producer means to publish (progress, ETA and span
  /// lengths are planned from it), >= 0. digits: of the frame numbers in file names
  /// (povgen::frame_digits of the scene's frame count; the manifest may not list a frame yet).
  FrameFeed(int expected_frames, int digits) : m_expected{expected_frames}, m_digits{digits} {}
  FrameFeed(const FrameFeed&) = delete;
  FrameFeed& operator=(const FrameFeed&) = delete;

  /// Producer: this frame's .pov (and mask .pov) are complete at their final names, and
  /// `entry` is its manifest entry (input_hash of what POV-Ray will read). Frames come in
  /// ascending order; a frame number published twice is a programming error (ignored).
  void publish(povgen::FrameEntry entry);
  /// Producer: nothing more will come (all frames published, or the producer stopped early).
  /// Idempotent.
  void close();

  struct Batch {
    std::vector<povgen::FrameEntry> frames;  ///< published since the previous take, ascending
    bool closed = false;                     ///< true: no frame will follow these
  };
  /// Consumer: takes what was published since the last call, without waiting.
  Batch take();

  [[nodiscard]] int expected_frames() const { return m_expected; }
  [[nodiscard]] int digits() const { return m_digits; }

 private:
  const int m_expected;
  const int m_digits;
  std::mutex m_mutex;
  std::vector<povgen::FrameEntry> m_ready;
  int m_last_number = 0;
  bool m_closed = false;
};

}  // namespace raintrace::render
