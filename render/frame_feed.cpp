// The hand-over between the exporter's thread and the renderer's.
#include "render/frame_feed.h"

#include <utility>

namespace raintrace::render {

void FrameFeed::publish(povgen::FrameEntry entry) {
  const std::lock_guard lock{m_mutex};
  if (m_closed || entry.number <= m_last_number) return;
  m_last_number = entry.number;
  m_ready.push_back(std::move(entry));
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
