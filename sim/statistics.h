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

/// Fall-speed bins per mm of diameter: bins 0.1 mm wide. A bin's mean speed belongs to the mean
/// diameter of its samples, not to its middle (Marshall-Palmer puts more drops at a bin's small
/// end); paired that way, the curvature of Gunn & Kinzer's curve inside a 0.1 mm bin moves the mean
/// speed by about v''·w²/24 ≈ 4 m/s/mm² · 0.01 mm² / 24 < 2 mm/s (Atlas et al. 1973's fit at 0.5
/// mm).
inline constexpr int kSpeedBinsPerMm = 10;
/// Bins cover [0, 10) mm: merging can grow drops past the 8 mm a scene may start with, up to
/// the largest breakup diameter (10 mm). Larger drops count in the last bin.
inline constexpr int kSpeedBinCount = 100;

/// Fall speed of the drops whose diameter lies in [diameter_min_mm, diameter_max_mm) (over all
/// frames fed). Plot speed against mean_diameter_mm, not against the bin's middle: drops are
/// not spread evenly inside a bin (Marshall-Palmer has many more small ones).
struct SpeedBin {
  double diameter_min_mm = 0.0;   ///< lower edge of the bin, mm (included)
  double diameter_max_mm = 0.0;   ///< upper edge, mm (excluded)
  double mean_diameter_mm = 0.0;  ///< mean diameter of the drops observed in the bin, mm
  double speed_m_per_s = 0.0;     ///< mean downward speed, m/s (0 when samples == 0)
  double speed_sd_m_per_s = 0.0;  ///< standard deviation of the downward speed, m/s
  std::uint64_t samples = 0;      ///< drop observations in the bin (one drop counts once a frame)
};

/// The horizontal motion at one frame: what gusts and turbulence do over time.
struct FrameMotion {
  double time_s = 0.0;  ///< simulated time of the frame, s
  /// Mean horizontal velocity of the drops in view [x, z], m/s (0 without drops).
  std::array<double, 2> drop_velocity_m_per_s{0.0, 0.0};
  /// Standard deviation of the drops' horizontal velocity [x, z] across the drops in view,
  /// m/s: how differently drops move at one instant (turbulence, drop sizes responding at
  /// different speeds to a changing wind).
  std::array<double, 2> drop_velocity_sd_m_per_s{0.0, 0.0};
  /// Wind at the camera's look_at point [x, z], m/s (steady + gusts + turbulence there).
  std::array<double, 2> wind_m_per_s{0.0, 0.0};
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
  std::vector<SpeedBin> fall_speed;            ///< kSpeedBinCount bins, 0.1 mm wide, from 0 mm
  std::array<double, 2> mean_horizontal_velocity_m_per_s{0.0, 0.0};  ///< [x, z] over drops
  std::vector<FrameMotion> motion;  ///< one entry per frame fed, in order
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
  std::vector<double> m_speed_square_sum;
  std::vector<double> m_bin_diameter_sum_mm;
  std::vector<std::uint64_t> m_speed_samples;
  std::vector<FrameMotion> m_motion;
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
