// Range checks of every SimParams field (ranges as documented in params.h and camera.h).
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "sim/world.h"

namespace raintrace::sim {
namespace {

std::string str(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// Written as !(inside) so that NaN is rejected too.
void in_range(double v, double lo, double hi, const char* name) {
  if (!(v >= lo && v <= hi)) {
    throw std::invalid_argument(std::string(name) + " must be in [" + str(lo) + ", " + str(hi) +
                                "] (got " + str(v) + ")");
  }
}

void open_range(double v, double lo, double hi, const char* name) {
  if (!(v > lo && v < hi)) {
    throw std::invalid_argument(std::string(name) + " must be in (" + str(lo) + ", " + str(hi) +
                                ") (got " + str(v) + ")");
  }
}

void positive(double v, const char* name) {
  if (!(v > 0.0 && std::isfinite(v))) {
    throw std::invalid_argument(std::string(name) + " must be > 0 (got " + str(v) + ")");
  }
}

void finite(const glm::dvec3& v, const char* name) {
  if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z))) {
    throw std::invalid_argument(std::string(name) + " must be finite");
  }
}

}  // namespace

void validate(const SimParams& p) {
  finite(p.camera.position, "camera.position");
  finite(p.camera.look_at, "camera.look_at");
  if (p.camera.position == p.camera.look_at) {
    throw std::invalid_argument("camera.look_at must differ from camera.position");
  }
  open_range(p.camera.fov_deg, 1.0, 170.0, "camera.fov_deg");
  positive(p.camera.aspect, "camera.aspect");
  in_range(p.camera.exposure_s, 0.0, 1.0, "camera.exposure_s");

  const RainParams& r = p.rain;
  in_range(r.rate_mm_per_h, 0.0, 500.0, "rain.rate_mm_per_h");
  in_range(r.diameter_min_mm, 0.1, 8.0, "rain.diameter_min_mm");
  in_range(r.diameter_max_mm, r.diameter_min_mm, 8.0, "rain.diameter_max_mm");
  positive(r.near_m, "rain.near_m");
  if (!(r.far_m > r.near_m)) {
    throw std::invalid_argument("rain.far_m must be > rain.near_m (got " + str(r.far_m) +
                                " <= " + str(r.near_m) + ")");
  }
  in_range(r.far_m, r.near_m, 1000.0, "rain.far_m");
  in_range(r.ceiling_margin_m, 0.0, 1000.0, "rain.ceiling_margin_m");
  in_range(r.breakup_diameter_mm, 4.0, 10.0, "rain.breakup_diameter_mm");
  in_range(r.vanishing_rate_per_s, 0.0, 100.0, "rain.vanishing_rate_per_s");
  in_range(r.colour.r, 0.0, 1.0, "rain.colour[0]");
  in_range(r.colour.g, 0.0, 1.0, "rain.colour[1]");
  in_range(r.colour.b, 0.0, 1.0, "rain.colour[2]");

  const WindParams& w = p.wind;
  in_range(w.velocity_m_per_s.x, -60.0, 60.0, "wind.velocity_m_per_s[0]");
  in_range(w.velocity_m_per_s.y, -60.0, 60.0, "wind.velocity_m_per_s[1]");
  in_range(w.velocity_m_per_s.z, -60.0, 60.0, "wind.velocity_m_per_s[2]");
  in_range(w.gust_strength, 0.0, 500.0, "wind.gust_strength");
  finite(w.gust_direction, "wind.gust_direction");
  in_range(w.turbulence_m_per_s, 0.0, 30.0, "wind.turbulence_m_per_s");
  in_range(w.turbulence_scale_m, 0.1, 100.0, "wind.turbulence_scale_m");

  in_range(p.splashes.droplets, 0, 32, "splashes.droplets");
  if (!(p.splashes.lifetime_s > 0.0 && p.splashes.lifetime_s <= 2.0)) {
    throw std::invalid_argument("splashes.lifetime_s must be in (0, 2] (got " +
                                str(p.splashes.lifetime_s) + ")");
  }

  const LightningParams& l = p.lightning;
  in_range(l.strikes_per_minute, 0.0, 600.0, "lightning.strikes_per_minute");
  in_range(l.generations, 1, 8, "lightning.generations");
  in_range(l.cloud_height_m, 10.0, 5000.0, "lightning.cloud_height_m");
  in_range(l.azimuth_deg, -180.0, 180.0, "lightning.azimuth_deg");
  in_range(l.azimuth_spread_deg, 0.0, 180.0, "lightning.azimuth_spread_deg");
  in_range(l.distance_m, 0.0, 1.0e5, "lightning.distance_m");
  in_range(l.distance_min_m, 0.0, 1.0e5, "lightning.distance_min_m");
  in_range(l.distance_max_m, l.distance_min_m, 1.0e5, "lightning.distance_max_m");
  if (!(l.trunk_radius_m > 0.0 && l.trunk_radius_m <= 10.0)) {
    throw std::invalid_argument("lightning.trunk_radius_m must be in (0, 10] (got " +
                                str(l.trunk_radius_m) + ")");
  }
  in_range(l.return_strokes, 1, 10, "lightning.return_strokes");
  in_range(l.flash_duration_s, 0.05, 2.0, "lightning.flash_duration_s");
  if (!std::isfinite(l.first_strike_s)) {
    throw std::invalid_argument("lightning.first_strike_s must be finite");
  }

  if (!std::isfinite(p.ground_y_m)) throw std::invalid_argument("ground_y_m must be finite");
  in_range(p.substep_s, 1e-4, 0.02, "substep_s");
  if (!(p.prewarm_s < 0.0)) in_range(p.prewarm_s, 0.0, 60.0, "prewarm_s");
  in_range(p.threads, 0, 1024, "threads");
}

}  // namespace raintrace::sim
