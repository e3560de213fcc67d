// The rain world: drops, splashes and lightning advanced in fixed substeps.
// Contract the rest of raintrace relies on (sim/ may add to it, not change it):
//   World world(params);                 // throws std::invalid_argument naming the bad field
//   world.advance_to(frame_time_s);      // whole substeps; prewarm happens before t = 0
//   Frame frame = world.snapshot(index); // copy of the state for the exporter
// The constructor fills the simulated box with rain at its steady-state density and then runs
// the prewarm, so time_s() == 0 afterwards and the first frame is already full of rain.
// A caller that must stay responsive (Ctrl-C during a long prewarm) hands the World a cancel
// flag: the stepping loops check it between substeps and throw sim::Cancelled once it is set.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <vector>

#include "sim/drop_size.h"
#include "sim/drop_state.h"
#include "sim/frame.h"
#include "sim/ground_impacts.h"
#include "sim/integrator.h"
#include "sim/lightning.h"
#include "sim/params.h"
#include "sim/puddles.h"
#include "sim/spawn_region.h"
#include "sim/view_volume.h"
#include "sim/wind.h"

namespace raintrace::sim {

/// Thrown by World's stepping loops (constructor, advance_to) once its cancel flag is set.
class Cancelled : public std::exception {
 public:
  [[nodiscard]] const char* what() const noexcept override { return "simulation cancelled"; }
};

/// What a scene asks of the simulation, known before any drop exists (World::estimate).
struct WorkEstimate {
  double drops = 0.0;          ///< drops simulated at steady state (in view or drifting into it)
  double drops_in_view = 0.0;  ///< of those, inside the view frustum [near_m, far_m]
  double prewarm_steps = 0.0;  ///< substeps before t = 0
  /// Substeps from the start of the prewarm to time t_s.
  [[nodiscard]] double steps_until(double t_s, double substep_s) const {
    return prewarm_steps + (t_s > 0.0 ? t_s / substep_s : 0.0);
  }
};

class World {
 public:
  /// Most drops a World will hold; more throws std::invalid_argument (reduce rain.far_m or
  /// rain.rate_mm_per_h).
  static constexpr double kMaxDrops = 50.0e6;

  /// cancel: when set (to true, by any thread), the prewarm and advance_to() stop at the next
  /// substep by throwing Cancelled; null = never cancelled.
  explicit World(const SimParams& params, const std::atomic<bool>* cancel = nullptr);

  /// The drop counts and prewarm length World(params) would have, from the same formulas but
  /// without simulating (cheap). Throws std::invalid_argument like the constructor for bad params.
  static WorkEstimate estimate(const SimParams& params);

  /// Advances in whole substeps to the last substep boundary at or before t_s (to within
  /// 1e-6 of a substep). A time in the past is a no-op: the world never runs backwards.
  void advance_to(double t_s);
  /// One substep (benchmarks and tests).
  void step();

  /// The state for the exporter: drops inside the view frustum [near_m, far_m], the splash
  /// droplets in flight and the ripples of recent ground impacts (sim/splash.h,
  /// sim/ripples.h: those near enough to show rings; farther water gets their roughness),
  /// visible bolts with their brightness, flash, wind at look_at and running totals.
  [[nodiscard]] Frame snapshot(int frame_index) const;

  /// Simulated time of the current state, s (negative during prewarm).
  [[nodiscard]] double time_s() const;
  /// Every simulated drop, in or out of view.
  [[nodiscard]] const Drops& drops() const { return m_state.drops; }
  /// Ground impacts of the last moments (volume and sampled), oldest first within each source.
  [[nodiscard]] const std::vector<GroundImpact>& ground_impacts() const { return m_impacts; }
  [[nodiscard]] const PuddleField& puddles() const { return m_puddles; }
  [[nodiscard]] const ImpactSampler& impact_sampler() const { return m_sampler; }
  [[nodiscard]] const SpawnRegion& region() const { return m_region; }
  [[nodiscard]] const ViewVolume& view() const { return m_view; }
  [[nodiscard]] const DropSizeModel& sizes() const { return m_sizes; }
  /// Water volume (m³) of drops that reached the measured ground area since t = 0.
  [[nodiscard]] double ground_water_m3() const { return m_ground_water_m3; }
  /// Drops coalesced and merged drops broken up since the start (prewarm included).
  [[nodiscard]] std::uint64_t merges() const { return m_merges; }
  [[nodiscard]] std::uint64_t breakups() const { return m_breakups; }

 private:
  void fill();
  void spawn(double t_s);
  void handle_events(double t_end_s);
  void sample_ground(double t_end_s);
  void add_ground_effects(Frame& frame) const;
  /// What the running totals count of one impact.
  struct Tally {
    double time_s = 0.0;
    float weight = 1.0f;
    bool splash = false;
    bool ripple = false;
  };
  Tally record_impact(const GroundImpact& impact);
  void count(const Tally& tally);
  void count_until(double t_end_s);
  /// How long an impact still shows (splash droplets or ripples), s.
  [[nodiscard]] double impact_memory_s() const;
  [[nodiscard]] int thread_count() const;
  void check_cancel() const;

  SimParams m_params;
  const std::atomic<bool>* m_cancel;
  ViewVolume m_view;
  Wind m_wind;
  DropSizeModel m_sizes;
  SpawnRegion m_region;
  PuddleField m_puddles;
  GroundDetail m_detail;
  ImpactSampler m_sampler;
  LightningSchedule m_schedule;
  std::vector<LightningSchedule::Strike> m_strikes;
  DropState m_state;
  std::vector<GroundImpact> m_impacts;
  std::int64_t m_next_slot = 0;    // first ground-impact slot not sampled yet
  std::vector<Tally> m_uncounted;  // sampled impacts still ahead of the clock, by time
  std::size_t m_uncounted_next = 0;
  // Splash droplets in flight at the last snapshot, kept in whole flight steps (splash.h), so
  // that each snapshot continues their flights instead of repeating them: the same droplets
  // whatever the snapshots taken. A cache of snapshot(), hence mutable.
  mutable std::vector<FlyingDroplet> m_flying;
  mutable double m_flying_until_s = -1e300;  // impacts up to this time are launched
  double m_volume_start_s = 0.0;             // when the volume's drops began (start of the prewarm)
  std::vector<StepEvents> m_events;
  std::vector<std::uint32_t> m_removals;
  std::int64_t m_step = 0;  // substeps taken since the start of the prewarm
  std::int64_t m_prewarm_steps = 0;
  std::uint64_t m_next_id = 0;
  int m_merge_every = 1;
  double m_ground_water_m3 = 0.0;
  std::uint64_t m_ground_hits = 0;
  double m_ground_impacts = 0.0;
  double m_splash_events = 0.0;
  double m_ripple_events = 0.0;
  std::uint64_t m_ground_impacts_simulated = 0;
  std::uint64_t m_merges = 0;
  std::uint64_t m_breakups = 0;
};

}  // namespace raintrace::sim
