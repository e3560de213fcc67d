// Accumulates per-frame observations into the run summary (see statistics.h).
#include "sim/statistics.h"

#include <algorithm>
#include <cmath>

namespace raintrace::sim {
namespace {
constexpr double kSecondsPerHour = 3600.0;
constexpr double kMmPerM = 1000.0;
}  // namespace

StatisticsCollector::StatisticsCollector(const SimParams& params)
    : m_configured_rate(params.rain.rate_mm_per_h),
      m_speed_sum(kSpeedBinCount, 0.0),
      m_speed_square_sum(kSpeedBinCount, 0.0),
      m_bin_diameter_sum_mm(kSpeedBinCount, 0.0),
      m_speed_samples(kSpeedBinCount, 0) {}

void StatisticsCollector::add(const Frame& frame) {
  if (m_frames == 0) {
    m_first_time = frame.time_s;
    m_first_impacts = frame.ground_impacts;
  }
  m_last_time = frame.time_s;
  ++m_frames;
  const Drops& drops = frame.drops;
  m_drop_sum += static_cast<double>(drops.size());
  if (frame.view_volume_m3 > 0.0) {
    m_density_sum += static_cast<double>(drops.size()) / frame.view_volume_m3;
  }
  double frame_vx = 0.0;
  double frame_vz = 0.0;
  double frame_vx2 = 0.0;
  double frame_vz2 = 0.0;
  for (std::size_t i = 0; i < drops.size(); ++i) {
    const double d_mm = static_cast<double>(drops.diameter[i]) * kMmPerM;
    m_diameter_sum_mm += d_mm;
    const auto vx = static_cast<double>(drops.velocity[i].x);
    const auto vz = static_cast<double>(drops.velocity[i].z);
    frame_vx += vx;
    frame_vz += vz;
    frame_vx2 += vx * vx;
    frame_vz2 += vz * vz;
    // Bin b holds [b·w, (b + 1)·w); the last one also everything larger.
    const int bin =
        std::clamp(static_cast<int>(std::floor(d_mm * kSpeedBinsPerMm)), 0, kSpeedBinCount - 1);
    const double down = -static_cast<double>(drops.velocity[i].y);
    m_speed_sum[bin] += down;
    m_speed_square_sum[bin] += down * down;
    m_bin_diameter_sum_mm[bin] += d_mm;
    ++m_speed_samples[bin];
  }
  m_vx_sum += frame_vx;
  m_vz_sum += frame_vz;
  FrameMotion motion;
  motion.time_s = frame.time_s;
  if (drops.size() > 0) {
    const auto n = static_cast<double>(drops.size());
    const double mx = frame_vx / n;
    const double mz = frame_vz / n;
    motion.drop_velocity_m_per_s = {mx, mz};
    motion.drop_velocity_sd_m_per_s = {std::sqrt(std::max(0.0, frame_vx2 / n - mx * mx)),
                                       std::sqrt(std::max(0.0, frame_vz2 / n - mz * mz))};
  }
  motion.wind_m_per_s = {frame.wind_m_per_s.x, frame.wind_m_per_s.z};
  m_motion.push_back(motion);
  m_ground_water_last_m3 = frame.ground_water_m3;
  m_ground_area_m2 = frame.ground_area_m2;
  m_impacts = frame.ground_impacts;
  m_splashes = frame.splash_events;
  m_ripples = frame.ripple_events;
  m_impacts_simulated = frame.ground_impacts_simulated;
  m_impact_area_m2 = frame.impact_area_m2;
  m_strikes = frame.lightning_strikes;
  for (const Bolt& bolt : frame.bolts) {
    if (m_bolt_ids.insert(bolt.id).second) m_segments += bolt.segments.size();
  }
}

Statistics StatisticsCollector::result() const {
  Statistics s;
  s.frames = m_frames;
  s.rain_rate_configured_mm_per_h = m_configured_rate;
  if (m_frames > 1) s.dt_s = (m_last_time - m_first_time) / (m_frames - 1);
  std::uint64_t observations = 0;
  for (int b = 0; b < kSpeedBinCount; ++b) {
    SpeedBin bin;
    // Divided, not multiplied by the width: 6 / 10 prints as 0.6, 6 · 0.1 as 0.6000000000000001.
    bin.diameter_min_mm = static_cast<double>(b) / kSpeedBinsPerMm;
    bin.diameter_max_mm = static_cast<double>(b + 1) / kSpeedBinsPerMm;
    bin.samples = m_speed_samples[b];
    if (bin.samples > 0) {
      const auto n = static_cast<double>(bin.samples);
      bin.mean_diameter_mm = m_bin_diameter_sum_mm[b] / n;
      bin.speed_m_per_s = m_speed_sum[b] / n;
      // Population standard deviation; max() keeps rounding from taking the root of −0.
      bin.speed_sd_m_per_s = std::sqrt(
          std::max(0.0, m_speed_square_sum[b] / n - bin.speed_m_per_s * bin.speed_m_per_s));
    }
    observations += bin.samples;
    s.fall_speed.push_back(bin);
  }
  if (m_frames > 0) {
    s.drop_count = m_drop_sum / m_frames;
    s.number_density_per_m3 = m_density_sum / m_frames;
  }
  if (observations > 0) {
    const auto n = static_cast<double>(observations);
    s.mean_diameter_mm = m_diameter_sum_mm / n;
    s.mean_horizontal_velocity_m_per_s = {m_vx_sum / n, m_vz_sum / n};
  }
  s.motion = m_motion;
  // The ground tally runs from t = 0, so the measured rate is the water depth over [0, t_last].
  if (m_last_time > 0.0 && m_ground_area_m2 > 0.0) {
    s.rain_rate_measured_mm_per_h =
        m_ground_water_last_m3 / m_ground_area_m2 * kMmPerM / m_last_time * kSecondsPerHour;
  }
  s.ground.impacts = static_cast<std::uint64_t>(std::llround(m_impacts));
  s.ground.splashes = static_cast<std::uint64_t>(std::llround(m_splashes));
  s.ground.ripples = static_cast<std::uint64_t>(std::llround(m_ripples));
  s.ground.impacts_simulated = m_impacts_simulated;
  s.ground.area_m2 = m_impact_area_m2;
  if (m_last_time > m_first_time && m_impact_area_m2 > 0.0) {
    s.ground.impacts_per_m2_s =
        (m_impacts - m_first_impacts) / (m_impact_area_m2 * (m_last_time - m_first_time));
  }
  s.splashes = s.ground.splashes;
  s.lightning_strikes = m_strikes;
  s.lightning_segments = m_segments;
  return s;
}

}  // namespace raintrace::sim
