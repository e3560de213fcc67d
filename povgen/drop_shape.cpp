// The exporter's view of sim's drop physics: Beard-Chuang from sim/drop_shape.h (clamped to
// the atlas's range) and the paper's eq. 3 from sim/streak.h, so both modules agree exactly.
#include "povgen/drop_shape.h"

#include <algorithm>

#include "sim/drop_shape.h"
#include "sim/streak.h"

namespace raintrace::povgen {

double drop_axis_ratio(double diameter_m) {
  return std::clamp(sim::axis_ratio(diameter_m), 0.5, 1.0);
}

double streak_length(double speed_m_per_s, double accel_m_per_s2, double exposure_s,
                     double radius_m) {
  return sim::streak_length(speed_m_per_s, accel_m_per_s2, exposure_s, 2.0 * radius_m);
}

}  // namespace raintrace::povgen
