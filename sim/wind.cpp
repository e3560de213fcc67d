// Wind field (see wind.h).
#include "sim/wind.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "sim/perpendicular_basis.h"
#include "sim/random.h"

namespace raintrace::sim {

double gust_function(double t) {
  constexpr double pi = std::numbers::pi;
  return std::cos(pi * t) * std::cos(3 * pi * t) * std::cos(5 * pi * t) * std::cos(7 * pi * t) *
         -kGustPeak * std::sin(25 * pi * t);
}

Wind::Wind(const WindParams& params, std::uint64_t seed)
    : m_params(params), m_turbulence(params.turbulence_m_per_s > 0.0) {
  const glm::dvec3 flat{params.gust_direction.x, 0.0, params.gust_direction.z};
  if (glm::length(flat) > 0.0) m_gust_dir = glm::normalize(flat);
  const double k = 2.0 * std::numbers::pi / params.turbulence_scale_m;
  // Each mode a·sin(k·x + φ) with a ⟂ k is divergence-free; the amplitude makes the RMS speed
  // of the sum equal turbulence_m_per_s (each mode carries a²/2 of the variance).
  const double amp = params.turbulence_m_per_s * std::sqrt(2.0 / kModes);
  for (int m = 0; m < kModes; ++m) {
    auto u = [&](int dim) { return uniform(seed, Stream::turbulence, m, dim); };
    const double cz = 2.0 * u(0) - 1.0, az = 2.0 * std::numbers::pi * u(1);
    const double sz = std::sqrt(1.0 - cz * cz);
    const glm::dvec3 dir{sz * std::cos(az), cz, sz * std::sin(az)};
    const PerpendicularBasis across = perpendicular_basis(dir);
    const double ap = 2.0 * std::numbers::pi * u(2);
    m_modes.k[m] = glm::vec3(dir * k);
    m_modes.amp[m] = glm::vec3((std::cos(ap) * across.u + std::sin(ap) * across.v) * amp);
    m_modes.phase[m] = static_cast<float>(2.0 * std::numbers::pi * u(3));
  }
  m_modes.drift = params.velocity_m_per_s;
}

glm::dvec3 Wind::uniform_at(double t_s) const {
  glm::dvec3 w = m_params.velocity_m_per_s;
  if (m_params.gusts) {
    // Eq. 5 unchanged, only its time axis stretched: gust_period_s = 2 is the paper as printed.
    const double t = t_s * kGustFunctionPeriodS / m_params.gust_period_s;
    w += m_gust_dir * (m_params.gust_strength * gust_function(t));
  }
  return w;
}

glm::vec3 Wind::turbulence_at(const glm::vec3& p, double t_s) const {
  if (!m_turbulence) return glm::vec3{0.0f};
  glm::vec3 w{0.0f};
  float scratch = 0.0f;
  turbulence_of(m_modes, t_s, 1, &p.x, &p.y, &p.z, &w.x, &w.y, &w.z, &scratch);
  return w;
}

glm::vec3 Wind::at(const glm::vec3& p, double t_s) const {
  return glm::vec3(uniform_at(t_s)) + turbulence_at(p, t_s);
}

double Wind::max_horizontal_speed() const {
  const glm::dvec3 v = m_params.velocity_m_per_s;
  double s = std::hypot(v.x, v.z);
  if (m_params.gusts) s += kGustPeak * m_params.gust_strength;
  if (m_turbulence) s += m_params.turbulence_m_per_s * std::sqrt(2.0 * kModes);
  return s;
}

double Wind::turbulence_lipschitz_per_s() const {
  if (!m_turbulence) return 0.0;
  // Each mode a·sin(k·q + φ) changes by at most |a|·|k|·|Δq|.
  double l = 0.0;
  for (int m = 0; m < kModes; ++m) {
    l += static_cast<double>(glm::length(m_modes.amp[m])) * glm::length(m_modes.k[m]);
  }
  return l;
}

}  // namespace raintrace::sim
