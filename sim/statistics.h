// Summary numbers of a simulated run, for `raintrace simulate` to serialise as JSON.
// StatisticsCollector is a pure accumulator: feed it every snapshot in order, read result().
// It knows nothing about files or JSON; the cli owner maps Statistics to keys.
#pragma once

#include <array>
#include <cstdint>
#include <set>
#include <vector>

#include "sim/frame.h"
#include "sim/params.h"

namespace raintrace::sim {

/// Mean fall speed of the drops in one diameter bin (over all frames fed).
struct SpeedBin {
  double diameter_mm = 0.0;    ///< centre of the bin, mm
  double speed_m_per_s = 0.0;  ///< mean downward speed, m/s (0 when samples == 0)
  std::uint64_t samples = 0;   ///< drop observations in the bin
};

/// Drops reaching the visible ground (sim/ground_impacts.h) since t = 0, up to the last frame.
/// Counts are estimates of the real numbers (level-of-detail weights summed), rounded.
struct GroundStatistics {
  std::uint64_t impacts = 0;            ///< drops that reached the visible ground
  std::uint64_t splashes = 0;           ///< of them, impacts above the splash threshold
  std::uint64_t ripples = 0;            ///< of them, impacts on puddles (ring ripples)
  std::uint64_t impacts_simulated = 0;  ///< impacts simulated one by one (the rest are weight)
  double area_m2 = 0.0;                 ///< ground they are counted over
  /// Impacts per m² per second between the first and the last frame (0 with one frame): the
  /// rain's number flux at the ground.
  double impacts_per_m2_s = 0.0;
};

struct Statistics {
  int frames = 0;                              ///< snapshots fed
  double dt_s = 0.0;                           ///< time between consecutive frames, s
  double drop_count = 0.0;                     ///< mean drops per frame in view
  double mean_diameter_mm = 0.0;               ///< mean drop diameter over all observations, mm
  double number_density_per_m3 = 0.0;          ///< mean drops per m³ in the view volume
  double rain_rate_configured_mm_per_h = 0.0;  ///< params.rain.rate_mm_per_h
  double rain_rate_measured_mm_per_h = 0.0;    ///< water reaching the ground, mm/h (0 if no time)
  std::vector<SpeedBin> fall_speed;            ///< by diameter, 0.5 mm bins from 0 to 8 mm
  std::array<double, 2> mean_horizontal_velocity_m_per_s{0.0, 0.0};  ///< [x, z] over drops
  std::uint64_t splashes = 0;  ///< impacts that splashed, up to the last frame (= ground.splashes)
  GroundStatistics ground;     ///< what reached the visible ground
  std::uint64_t lightning_strikes = 0;   ///< distinct bolts seen (and struck) up to last frame
  std::uint64_t lightning_segments = 0;  ///< segments summed over the distinct bolts seen
};

class StatisticsCollector {
 public:
  explicit StatisticsCollector(const SimParams& params);

  /// Adds one snapshot. Frames must come in increasing time order; the ground tally and the
  /// splash/strike totals are read from the last frame, everything else averaged over frames.
  void add(const Frame& frame);

  /// The numbers so far. Valid after zero frames too (all zeros except the configured rate).
  [[nodiscard]] Statistics result() const;

 private:
  double m_configured_rate = 0.0;
  int m_frames = 0;
  double m_first_time = 0.0;
  double m_last_time = 0.0;
  double m_drop_sum = 0.0;
  double m_diameter_sum_mm = 0.0;
  double m_density_sum = 0.0;
  double m_vx_sum = 0.0;
  double m_vz_sum = 0.0;
  std::vector<double> m_speed_sum;
  std::vector<std::uint64_t> m_speed_samples;
  double m_ground_water_last_m3 = 0.0;
  double m_ground_area_m2 = 0.0;
  double m_first_impacts = 0.0;  // the ground's running totals: first frame, last frame
  double m_impacts = 0.0;
  double m_splashes = 0.0;
  double m_ripples = 0.0;
  std::uint64_t m_impacts_simulated = 0;
  double m_impact_area_m2 = 0.0;
  std::uint64_t m_strikes = 0;
  std::set<std::uint64_t> m_bolt_ids;
  std::uint64_t m_segments = 0;
};

}  // namespace raintrace::sim
