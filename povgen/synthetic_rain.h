// Hand-made rain for tests and benchmarks of the exporter, without running the simulation:
// drops spread uniformly through the camera's view out to far_m, falling at their terminal
// speed (Atlas et al. 1973 fit), deterministic for a seed.
#pragma once

#include <cstddef>
#include <cstdint>

#include "sim/camera.h"
#include "sim/frame.h"

namespace raintrace::povgen {

/// `count` drops in the view of `camera` (aspect `aspect`) between 0.3 m and far_m deep,
/// diameters uniform in [0.5, 3] mm, falling at terminal speed with wind wind_x_m_per_s.
sim::Frame synthetic_rain(std::size_t count, const sim::Camera& camera, double aspect,
                          double far_m = 12.0, double wind_x_m_per_s = 0.0, std::uint64_t seed = 1);

}  // namespace raintrace::povgen
