// Progress of a render: elapsed time and the ETA (progress.h).
#include "render/progress.h"

#include <algorithm>

namespace raintrace::render {

void ProgressReporter::report() {
  auto& p = m_progress;
  const auto now = Clock::now();
  p.elapsed_seconds = std::chrono::duration<double>(now - m_start).count();
  const int finished = p.done + p.failed;
  std::optional<double> paced;
  if (m_pace) {
    // A traced image is done once developed, a second or two later: not left to trace.
    const int awaiting_develop =
        std::max(m_pace->finished_count() - (p.done - p.developed_only), 0);
    paced = m_pace->seconds_left(p.total - finished - awaiting_develop, now);
  }
  if (paced) {
    p.eta_seconds = *paced;
  } else {
    p.eta_seconds = finished > 0 ? p.elapsed_seconds / finished * (p.total - finished) : -1.0;
  }
  if (m_on_progress) m_on_progress(p);
}

}  // namespace raintrace::render
