// Beard-Chuang axis ratio and the paper's streak length.
#include "povgen/drop_shape.h"

#include <algorithm>

namespace raintrace::povgen {

double drop_axis_ratio(double diameter_m) {
  const double d = diameter_m * 100.0;  // the fit is in centimetres
  const double ratio = 1.0048 + d * (0.0057 + d * (-2.628 + d * (3.682 + d * -1.677)));
  return std::clamp(ratio, 0.5, 1.0);
}

double streak_length(double speed_m_per_s, double accel_m_per_s2, double exposure_s,
                     double radius_m) {
  const double travel = speed_m_per_s * exposure_s + 0.5 * accel_m_per_s2 * exposure_s * exposure_s;
  return std::max(travel, 0.0) + 2.0 * radius_m;
}

}  // namespace raintrace::povgen
