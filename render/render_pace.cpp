// The remaining time of a render from its processes' pace (render_pace.h).
#include "render/render_pace.h"

#include <algorithm>
#include <numeric>

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

std::optional<double> RenderPace::mean_cost(double share) const {
  if (!m_recent_costs.empty()) {
    return std::accumulate(m_recent_costs.begin(), m_recent_costs.end(), 0.0) /
           static_cast<double>(m_recent_costs.size());
  }
  // None finished yet: the whole costs of the pictures in flight that have a rate of their own.
  double costs = 0.0;
  int counted = 0;
  for (const auto& [key, picture] : m_in_flight) {
    const double had = picture.had + share;
    if (const auto left = left_at_own_rate(picture, had)) {
      costs += had + *left;
      ++counted;
    }
  }
  if (counted == 0) return std::nullopt;
  return costs / counted;
}

std::optional<double> RenderPace::seconds_left(int untraced, Clock::time_point now) const {
  const double share = share_since_last_event(now);
  const std::optional<double> mean = mean_cost(share);
  if (!mean) return std::nullopt;
  double left = 0.0;
  for (const auto& [key, picture] : m_in_flight) {
    const double had = picture.had + share;
    left += left_at_own_rate(picture, had).value_or(std::max(*mean - had, 0.0));
  }
  const int queued = std::max(untraced - static_cast<int>(m_in_flight.size()), 0);
  return left + queued * *mean;
}

}  // namespace raintrace::render
