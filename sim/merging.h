// Merging (paper §3.3): drops that touched during the last interval coalesce into one drop,
// conserving water volume and momentum. The test is swept: two drops touch if the closest
// approach of their relative straight-line motion over the interval (limited to the younger
// drop's age) is within the sum of their radii — fast drops overtaking slow ones within one
// interval are not missed.
//
// Candidate pairs come from a grid of vertical columns over the drops' positions at the middle
// of the interval (p − v·W/2), sorted by column with a counting sort, so a pass is O(n). Seen
// from the middle of the interval, two drops that touch at any time in it are at most
// touch + |Δv|·W/2 apart along each axis — half what the end positions allow. The bound on
// the relative velocity Δv is measured from the drops themselves each pass, not assumed:
// Δv = ΔT + Δs, where T is the wind's turbulence at a drop (Lipschitz, so ΔT is tiny over the
// millimetres between touching drops) and s = v − T is the drop's slip through the air, whose
// spread over all drops is measured. Uniform wind and gusts move every drop alike and cancel.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/drop_state.h"
#include "sim/wind.h"

namespace raintrace::sim {

struct MergeResult {
  std::size_t merges = 0;    ///< pairs coalesced
  std::size_t breakups = 0;  ///< merged drops that then broke up
};

/// Bounds one merging pass derived from the drops (for benchmarks and tests).
struct MergeBounds {
  float touch_m = 0.0f;     ///< largest touching distance: the largest diameter
  glm::vec3 dv_m_per_s{};   ///< per axis, bound on |Δv| of any pair that can touch
  float column_m = 0.0f;    ///< column width of the candidate grid
  float vertical_m = 0.0f;  ///< bound on the vertical distance of candidate midpoints
};

/// One merging pass over the motion of the last interval_s. wind (may be null: no turbulence)
/// gives the turbulence at time_s, whose spatial variation the relative-velocity bound must
/// allow for. Merged drops past breakup_diameter_m break up (breakup.h). Surviving drops keep
/// their relative order; the larger drop of a pair keeps its id. Deterministic for a given
/// drop order. bounds, if not null, receives the bounds used.
MergeResult merge_touching(DropState& state, float interval_s, double breakup_diameter_m,
                           std::uint64_t& next_id, std::uint64_t seed, const Wind* wind = nullptr,
                           double time_s = 0.0, MergeBounds* bounds = nullptr);

}  // namespace raintrace::sim
