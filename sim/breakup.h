// Breakup (paper §3.3): a drop grown past the critical diameter is hydrodynamically unstable
// and splits into smaller drops. Volume is conserved exactly up to float rounding.
#pragma once

#include <cstddef>
#include <cstdint>

#include "sim/drop_state.h"

namespace raintrace::sim {

/// Splits drop i if its diameter exceeds breakup_diameter_m into n = max(2, ⌈2·D³/Dc³⌉)
/// fragments of jittered volume fractions (each below 0.83·Dc³, so none needs to break again).
/// Fragment 0 stays at index i with the drop's id; the others are appended with ids
/// next_id, next_id+1, … Fragments are newborn (age 0) and drift apart sideways.
/// Returns the number of drops appended (0 if the drop was small enough).
std::size_t break_up(DropState& state, std::size_t i, double breakup_diameter_m,
                     std::uint64_t& next_id, std::uint64_t seed);

}  // namespace raintrace::sim
