// The remaining time of a local render from its processes' pace (render_pace.h).
#include "render/render_pace.h"

#include <algorithm>

namespace raintrace::render {

double RenderPace::share_since_last_event(Clock::time_point now) const {
  if (m_in_flight.empty()) return 0.0;
  const double seconds = std::chrono::duration<double>(now - m_last_event).count();
  return std::max(seconds, 0.0) / static_cast<double>(m_in_flight.size());
}

void RenderPace::advance(Clock::time_point now) {
  const double share = share_since_last_event(now);
  for (auto& [key, picture] : m_in_flight) picture.had += share;
  m_last_event = std::max(m_last_event, now);
}

void RenderPace::started(Pass pass, const FrameSpan& span, Clock::time_point now) {
  advance(now);
  m_in_flight[{pass, span.first}] = InFlight{0.0, span.last};
}

void RenderPace::finished(Pass pass, int frame, Clock::time_point now) {
  advance(now);
  const auto it = m_in_flight.find({pass, frame});
  if (it == m_in_flight.end()) return;
  ++m_finished;
  m_finished_cost += it->second.had;
  const int last = it->second.last;
  m_in_flight.erase(it);
  if (frame < last) m_in_flight[{pass, frame + 1}] = InFlight{0.0, last};
}

void RenderPace::failed(Pass pass, int frame, Clock::time_point now) {
  advance(now);
  m_in_flight.erase({pass, frame});
}

std::optional<double> RenderPace::seconds_left(int untraced, Clock::time_point now) const {
  if (m_finished == 0) return std::nullopt;
  const double mean = m_finished_cost / m_finished;
  const double share = share_since_last_event(now);
  double left = 0.0;
  for (const auto& [key, picture] : m_in_flight) left += std::max(mean - picture.had - share, 0.0);
  const int queued = std::max(untraced - static_cast<int>(m_in_flight.size()), 0);
  return left + queued * mean;
}

}  // namespace raintrace::render
