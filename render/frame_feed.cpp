// The hand-over between the exporter's thread and the renderer's.
#include "render/frame_feed.h"

#include <utility>

namespace raintrace::render {

void FrameFeed::publish(output::ExportedFrame frame) {
  const std::lock_guard lock{m_mutex};
  if (m_closed || frame.number <= m_last_number) return;
  m_last_number = frame.number;
  m_ready.push_back(std::move(frame));
}

void FrameFeed::close() {
  const std::lock_guard lock{m_mutex};
  m_closed = true;
}

FrameFeed::Batch FrameFeed::take() {
  const std::lock_guard lock{m_mutex};
  Batch batch;
  batch.frames.swap(m_ready);
  batch.closed = m_closed;
  return batch;
}

}  // namespace raintrace::render
