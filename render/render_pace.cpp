// The remaining time of a local render from its processes' pace (render_pace.h).
#include "render/render_pace.h"

#include <algorithm>
#include <numeric>
#include <vector>

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
  m_recent_costs.push_back(it->second.had);
  if (m_recent_costs.size() > kRecentFinished) m_recent_costs.pop_front();
  const int last = it->second.last;
  m_in_flight.erase(it);
  if (frame < last) m_in_flight[{pass, frame + 1}] = InFlight{0.0, last};
}

void RenderPace::failed(Pass pass, int frame, Clock::time_point now) {
  advance(now);
  m_in_flight.erase({pass, frame});
}

void RenderPace::traced(Pass pass, int frame, double share, Clock::time_point now) {
  advance(now);
  const auto it = m_in_flight.find({pass, frame});
  if (it == m_in_flight.end()) return;
  InFlight& picture = it->second;
  if (picture.first_share < 0.0 || share < picture.share) {
    picture.first_share = share;
    picture.first_had = picture.had;
  }
  picture.share = share;
  picture.share_had = picture.had;
}

std::optional<double> RenderPace::left_at_own_rate(const InFlight& picture, double had) {
  const double traced = picture.share - picture.first_share;
  if (picture.first_share < 0.0 || traced < kMinTracedShare) return std::nullopt;
  const double at_report = (1.0 - picture.share) * (picture.share_had - picture.first_had) / traced;
  return std::max(at_report - (had - picture.share_had), 0.0);
}

std::optional<double> RenderPace::seconds_left(int untraced, Clock::time_point now) const {
  const double share = share_since_last_event(now);
  // Each picture in flight: what is left of it at its own rate, if it has one.
  std::vector<std::optional<double>> own;
  own.reserve(m_in_flight.size());
  double own_costs = 0.0;
  int with_own = 0;
  for (const auto& [key, picture] : m_in_flight) {
    own.push_back(left_at_own_rate(picture, picture.had + share));
    if (own.back()) {
      own_costs += picture.had + share + *own.back();
      ++with_own;
    }
  }
  double mean = 0.0;
  if (!m_recent_costs.empty()) {
    mean = std::accumulate(m_recent_costs.begin(), m_recent_costs.end(), 0.0) /
           static_cast<double>(m_recent_costs.size());
  } else if (with_own > 0) {
    mean = own_costs / with_own;
  } else {
    return std::nullopt;
  }
  double left = 0.0;
  std::size_t i = 0;
  for (const auto& [key, picture] : m_in_flight) {
    left += own[i] ? *own[i] : std::max(mean - picture.had - share, 0.0);
    ++i;
  }
  const int queued = std::max(untraced - static_cast<int>(m_in_flight.size()), 0);
  return left + queued * mean;
}

}  // namespace raintrace::render
