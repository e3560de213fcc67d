// Streak length (paper eq. 3) and time coverage (Garg & Nayar 2006), see streak.h.
#include "sim/streak.h"

#include <algorithm>
#include <cmath>

namespace raintrace::sim {

double streak_travel(double speed_m_per_s, double accel_m_per_s2, double exposure_s) {
  return std::max(speed_m_per_s * exposure_s + 0.5 * accel_m_per_s2 * exposure_s * exposure_s, 0.0);
}

double streak_length(double speed_m_per_s, double accel_m_per_s2, double exposure_s,
                     double diameter_m) {
  return streak_travel(speed_m_per_s, accel_m_per_s2, exposure_s) + diameter_m;
}

double streak_time_coverage(double along_m, double across_m, double travel_m, double diameter_m) {
  const double radius = 0.5 * diameter_m;
  if (!(radius > 0.0) || std::fabs(across_m) >= radius) return 0.0;
  // Half the chord of the disc at this offset: the point is covered while the disc's centre is
  // within h of it along the axis. The centre runs from R to R + travel.
  const double h = std::sqrt(radius * radius - across_m * across_m);
  const double lo = std::max(along_m - h, radius);
  const double hi = std::min(along_m + h, radius + travel_m);
  if (travel_m <= 0.0) return std::fabs(along_m - radius) < h ? 1.0 : 0.0;
  return std::clamp((hi - lo) / travel_m, 0.0, 1.0);
}

double streak_opacity(double travel_m, double diameter_m) {
  return travel_m > diameter_m ? diameter_m / travel_m : 1.0;
}

}  // namespace raintrace::sim
