// Terminal velocity fit (see terminal_velocity.h for the sources).
#include "sim/terminal_velocity.h"

#include <algorithm>
#include <cmath>

namespace raintrace::sim {
namespace {
double atlas(double d_mm) { return 9.65 - 10.3 * std::exp(-0.6 * d_mm); }
constexpr double kSmallMm = 0.1;      // Gunn & Kinzer's smallest tabulated drop
constexpr double kSmallSpeed = 0.27;  // its speed, m/s
constexpr double kJoinMm = 0.5;       // where the Atlas fit takes over
}  // namespace

double terminal_velocity(double diameter_m) {
  const double d_mm = diameter_m * 1000.0;
  if (d_mm <= 0.0) return 0.0;
  if (d_mm >= kJoinMm) return atlas(d_mm);
  if (d_mm >= kSmallMm) {
    const double slope = (atlas(kJoinMm) - kSmallSpeed) / (kJoinMm - kSmallMm);
    return kSmallSpeed + slope * (d_mm - kSmallMm);
  }
  const double r = d_mm / kSmallMm;
  return kSmallSpeed * r * r;
}

double drag_coefficient(double diameter_m) {
  // Floor the speed so a vanishingly small drop gets a large but finite coefficient.
  const double v = std::max(terminal_velocity(diameter_m), 1e-3);
  return kGravity / (v * v);
}

}  // namespace raintrace::sim
