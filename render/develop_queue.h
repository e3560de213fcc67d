// Developing rendered frames (images/frame_NNNN.exr → images/frame_NNNN.png, film/develop.h) in
// a render run. Develop costs a few per cent of a frame's POV-Ray time, so it runs on a thread of
// its own fed by a queue: POV-Ray's processes are started and polled as if it were not there, and
// the progress display keeps moving. The folder's state is not thread-safe, so results come back
// through DevelopQueue::take() on the thread that owns the state, which records them.
//
// One rule keeps a folder honest, as for POV-Ray's images: a PNG reaches its final name only
// after it was written whole under images/.tmp/ and decodes completely at the frame's size. A
// killed run leaves no PNG that looks finished; the frame's EXR stays rendered, and the next run
// develops it.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "film/develop.h"
#include "output/folder_state.h"

namespace raintrace::render {

/// What developing a folder's frames needs to know, from its manifest.
struct DevelopTarget {
  film::DevelopSettings settings;
  double fov_deg = 60.0;    ///< for vignetting and the diffraction spikes
  double aperture_m = 0.0;  ///< for the diffraction spikes
  std::uint64_t seed = 1;   ///< for grain, with each frame's number
  int width = 0;            ///< the frames' size: the PNG must decode at it
  int height = 0;
  int digits = 4;  ///< digits of frame numbers in file names
};

/// The target of a folder: its manifest's develop spec, seed, size and frame-number digits.
DevelopTarget develop_target(const output::Manifest& manifest);

/// Loads Blender's Filmic configuration once for the run (throws std::runtime_error with one
/// line naming the Debian package blender-data when it is missing) and gives `folder` this run's
/// develop hash (output::develop_hash), so its plan knows which PNGs are current.
std::unique_ptr<film::DisplayTransform> prepare_develop(output::FolderState& folder);

struct DevelopResult {
  int frame = 0;
  bool only = false;  ///< the frame's EXR was current: this run developed it without rendering
  double seconds = 0.0;
  /// Empty when the PNG is at its final name, verified; otherwise one line saying why not.
  std::string error;
};

/// Develops one frame on the calling thread: its EXR (final name) into a PNG under images/.tmp/,
/// verified, then renamed to developed_image_name(). Never throws: failures are in the result.
DevelopResult develop_frame(const std::filesystem::path& out_dir, int frame,
                            const DevelopTarget& target, const film::DisplayTransform& display);

/// One thread developing the frames submitted to it, in order.
class DevelopQueue {
 public:
  /// `display` must outlive the queue. stop (set from a signal handler; may be null): the
  /// frame in hand is finished, the frames still queued are left (the next run develops them).
  DevelopQueue(std::filesystem::path out_dir, DevelopTarget target,
               const film::DisplayTransform& display, const std::atomic<bool>* stop = nullptr);
  /// Finishes the frame in hand, leaves the rest, and joins the thread.
  ~DevelopQueue();
  DevelopQueue(const DevelopQueue&) = delete;
  DevelopQueue& operator=(const DevelopQueue&) = delete;

  /// Queues a frame whose EXR is rendered and recorded; `only`: it was not rendered in this run
  /// (carried into its result, for the counts).
  void submit(int frame, bool only = false);
  /// Results finished since the last call, in the order they finished.
  std::vector<DevelopResult> take();
  /// True when no frame is queued or being developed (or, once stopped, none is in hand).
  [[nodiscard]] bool idle() const;

 private:
  void work();
  [[nodiscard]] bool stopped() const { return m_stop != nullptr && m_stop->load(); }

  std::filesystem::path m_out;
  DevelopTarget m_target;
  const film::DisplayTransform& m_display;
  const std::atomic<bool>* m_stop;
  mutable std::mutex m_mutex;
  std::condition_variable m_wake;
  std::deque<std::pair<int, bool>> m_queue;  // frame, only
  std::vector<DevelopResult> m_done;
  bool m_busy = false;
  bool m_closing = false;
  std::thread m_thread;  // last: started once everything above exists
};

}  // namespace raintrace::render
