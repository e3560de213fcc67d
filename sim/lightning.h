// Lightning (paper §3.5): strikes arrive as a Poisson process; each bolt is an L-system
// skeleton — a trunk stepping from the cloud base to the ground in shrinking, jittered steps,
// and branches whose counts per generation follow the Fibonacci numbers (the rabbit rule
// A → AB, B → A: every branch of the previous generation sprouts one child, and those that
// were already "mature" — the first count(g−2) — sprout a second) — with a flash envelope of
// several return strokes.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/camera.h"
#include "sim/frame.h"
#include "sim/params.h"

namespace raintrace::sim {

/// Branch counts per generation g = 0 … generations−1: F(g+1) = 1, 1, 2, 3, 5, 8, …
std::vector<int> fibonacci_branch_counts(int generations);

struct BoltBranch {
  int generation = 0;  ///< 0 = trunk
  int parent = -1;     ///< index of the parent branch in BoltSkeleton::branches, −1 for trunk
  std::vector<BoltSegment> segments;  ///< consecutive: segments[k].end == segments[k+1].start
};

struct BoltSkeleton {
  std::vector<BoltBranch> branches;  ///< ordered by generation, trunk first
};

/// True for the strike a clip opens with: the forced one (strike 0) when first_strike_s is set,
/// otherwise the first of the random ones (strike 1). It lands at azimuth_deg and distance_m.
bool is_first_strike(const LightningParams& params, std::uint64_t strike);

/// The skeleton of strike number `strike`: a pure function of its arguments. The first strike
/// lands at azimuth_deg from the camera's horizontal view direction, distance_m away; later
/// ones within ±azimuth_spread_deg of it, distance_min_m to distance_max_m away.
BoltSkeleton build_bolt(const LightningParams& params, const Camera& camera, double ground_y_m,
                        std::uint64_t seed, std::uint64_t strike);

/// The channel's fine structure, which the skeleton's steps (tens of metres) leave out: a
/// photographed channel bends every few metres. Hill (1968, "Analysis of irregular paths of
/// lightning channels", J. Geophys. Res. 73, 1897) measured pieces of ~5 m between kinks and a
/// mean absolute change of direction of 16° from one piece to the next. Every segment of
/// `bolt` longer than kKinkSpacingM is split by midpoint displacement — its midpoint moved at
/// right angles to it by a 2-D Gaussian of σ = kKinkSigma × its length, then each half split
/// again — until every piece is at most kKinkSpacingM long; a midpoint never goes below
/// ground_y_m. Ends, radius, generation and branch structure are kept; a pure function of its
/// arguments.
inline constexpr double kKinkSpacingM = 5.0;
/// Chosen so that consecutive pieces differ by 16° on average (lightning_test.cpp measures it):
/// one split alone bends by 2·atan(2|d|/l), 16° on average at σ = 0.056 (mean |d| = σ·√(π/2)),
/// but the bends of the coarser splits add to the finest ones' at their joints.
inline constexpr double kKinkSigma = 0.048;
BoltSkeleton with_kinks(const BoltSkeleton& bolt, double ground_y_m, std::uint64_t seed,
                        std::uint64_t strike);

/// Flash brightness at `since_strike_s` after the strike: the sum of `return_strokes` strokes
/// spread over flash_duration_s, each a sharp rise and exponential decay (time constant
/// flash_duration_s / (4·return_strokes)), the first peaking at 1, later ones at 0.6–1. A
/// stroke has decayed below e^−3 of its peak before the next begins, so the sum never exceeds
/// its peaks by more than 1/(e³ − 1) ≈ 5.2 %. 0 before the strike and after flash_duration_s.
double flash_envelope(const LightningParams& params, double since_strike_s, std::uint64_t seed,
                      std::uint64_t strike);

/// What a camera records of a flash in one frame: the envelope averaged over the exposure, the
/// shutter open from `since_open_s` after the strike for `exposure_s` (exposure_s = 0: the
/// envelope at since_open_s). `first_stroke` is the same for the first return stroke alone:
/// later strokes retrace the main channel only, so the branches glow with the first.
struct FlashExposure {
  double all_strokes = 0.0;
  double first_stroke = 0.0;
};
FlashExposure flash_exposure(const LightningParams& params, double since_open_s, double exposure_s,
                             std::uint64_t seed, std::uint64_t strike);

/// Brightness of a branch of `generation` (≥ 1) relative to the first stroke in the trunk: a
/// branch is a stepped leader that never connected, carrying a fraction of the current; each
/// generation carries less. 0.35 for the first, × 0.5 per further generation.
double branch_brightness(int generation);

/// Strike times: optional forced first_strike_s (strike 0) and a Poisson process of rate
/// strikes_per_minute from t = 0 (strikes 1, 2, …). Lazily extended, deterministic in seed.
class LightningSchedule {
 public:
  LightningSchedule(const LightningParams& params, std::uint64_t seed);

  struct Strike {
    std::uint64_t id = 0;
    double time_s = 0.0;
  };
  /// Strikes with time_s <= t_s, in time order.
  std::vector<Strike> strikes_until(double t_s);

 private:
  LightningParams m_params;
  std::uint64_t m_seed = 0;
  std::vector<double> m_poisson;  // times of strikes 1, 2, … generated so far
};

}  // namespace raintrace::sim
