// Beard & Chuang (1987) axis-ratio polynomial (see drop_shape.h).
#include "sim/drop_shape.h"

#include <algorithm>

namespace raintrace::sim {

double axis_ratio(double diameter_m) {
  const double d = std::clamp(diameter_m * 100.0, 0.0, 0.9);  // cm
  const double ratio = 1.0048 + d * (0.0057 + d * (-2.628 + d * (3.682 + d * -1.677)));
  return std::min(ratio, 1.0);
}

}  // namespace raintrace::sim
