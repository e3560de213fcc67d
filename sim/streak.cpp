// Paper eq. 3 (see streak.h).
#include "sim/streak.h"

#include <algorithm>

namespace raintrace::sim {

double streak_length(double speed_m_per_s, double accel_m_per_s2, double exposure_s,
                     double diameter_m) {
  const double travel = speed_m_per_s * exposure_s + 0.5 * accel_m_per_s2 * exposure_s * exposure_s;
  // A decelerating drop never moves backwards within one exposure.
  return std::max(travel, 0.0) + diameter_m;
}

}  // namespace raintrace::sim
