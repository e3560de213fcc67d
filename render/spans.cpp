// Span cutting.
#include "render/spans.h"

#include <algorithm>
#include <thread>

namespace raintrace::render {

std::vector<FrameSpan> split_into_spans(const std::vector<int>& frames, int jobs, int max_span) {
  std::vector<FrameSpan> spans;
  if (frames.empty()) return spans;
  jobs = std::max(jobs, 1);
  max_span = std::max(max_span, 1);
  const int total = static_cast<int>(frames.size());
  const int target = std::clamp((total + 2 * jobs - 1) / (2 * jobs), 1, max_span);
  std::size_t i = 0;
  while (i < frames.size()) {
    FrameSpan span{frames[i], frames[i]};
    ++i;
    while (i < frames.size() && frames[i] == span.last + 1 && span.count() < target) {
      span.last = frames[i];
      ++i;
    }
    spans.push_back(span);
  }
  return spans;
}

int streaming_span_length(int expected_frames, int jobs, int max_span) {
  jobs = std::max(jobs, 1);
  return std::clamp((expected_frames + 2 * jobs - 1) / (2 * jobs), 1, std::max(max_span, 1));
}

void StreamingSpans::arrived(int number, bool needs_render) {
  if (m_closed || number <= m_last_arrived) return;
  m_last_arrived = number;
  if (needs_render) m_pending.push_back(number);
}

void StreamingSpans::close(int jobs) {
  if (m_closed) return;
  m_closed = true;
  const int left = static_cast<int>(m_pending.size());
  m_length = std::clamp((left + std::max(jobs, 1) - 1) / std::max(jobs, 1), 1, m_length);
}

std::optional<FrameSpan> StreamingSpans::take_ready() {
  if (m_pending.empty()) return std::nullopt;
  FrameSpan span{m_pending.front(), m_pending.front()};
  std::size_t n = 1;
  while (n < m_pending.size() && m_pending[n] == span.last + 1 && span.count() < m_length) {
    span.last = m_pending[n];
    ++n;
  }
  // Short of `length`: ready only if the run can no longer grow (its next frame has arrived
  // and needs no render, or nothing more arrives).
  const bool can_grow = !m_closed && span.last == m_last_arrived;
  if (span.count() < m_length && can_grow) return std::nullopt;
  m_pending.erase(m_pending.begin(), m_pending.begin() + static_cast<std::ptrdiff_t>(n));
  return span;
}

int default_jobs() {
  const int cores = static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  return cores / 2 + 3;
}

}  // namespace raintrace::render
