// Test and benchmark support, not part of raintrace_povgen: hand-made rain for the exporter,
// without running the simulation. Drops are spread uniformly through the camera's view out to
// far_m and fall at their terminal speed (sim::terminal_velocity); drop i is the same whatever
// the count, and the whole frame the same for a seed.
#pragma once

#include <cstddef>
#include <cstdint>

#include "sim/camera.h"
#include "sim/frame.h"

namespace raintrace::povgen::test_support {

/// `count` drops in the view of `camera` (aspect `aspect`) between 0.3 m and far_m deep,
/// diameters uniform in [0.5, 3] mm, falling at terminal speed with wind wind_x_m_per_s.
sim::Frame synthetic_rain(std::size_t count, const sim::Camera& camera, double aspect,
                          double far_m = 12.0, double wind_x_m_per_s = 0.0, std::uint64_t seed = 1);

}  // namespace raintrace::povgen::test_support
