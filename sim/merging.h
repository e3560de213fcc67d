// Merging (paper §3.3): drops that touched during the last interval coalesce into one drop,
// conserving water volume and momentum. Candidate pairs come from a uniform grid of vertical
// columns (drops sorted by column with a counting sort), so a pass is O(n); a drop's 3×3
// neighbour columns are three contiguous runs of the sorted copy, scanned sequentially. The test is
// swept: two drops touch if the closest approach of their relative straight-line motion over the
// interval (limited to the younger drop's age) is within the sum of their radii — fast drops
// overtaking slow ones within one interval are not missed.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/drop_state.h"

namespace raintrace::sim {

struct MergeResult {
  std::size_t merges = 0;    ///< pairs coalesced
  std::size_t breakups = 0;  ///< merged drops that then broke up
};

/// One merging pass. Columns are cell_h_m wide: at least the largest touching distance plus the
/// largest horizontal relative displacement over interval_s; cell_v_m bounds the vertical
/// distance of candidates the same way (relative motion is mostly vertical — different fall
/// speeds — so columns stay narrow). Merged drops past breakup_diameter_m break up
/// (breakup.h). Surviving drops keep their relative order; the larger drop of a pair keeps
/// its id. Deterministic for a given drop order.
MergeResult merge_touching(DropState& state, float interval_s, float cell_h_m, float cell_v_m,
                           double breakup_diameter_m, std::uint64_t& next_id, std::uint64_t seed);

}  // namespace raintrace::sim
