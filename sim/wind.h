// Wind field: steady vector + the paper's gust function w(t) (eq. 5) + optional smooth,
// divergence-free spatial turbulence (a few seeded Fourier modes, frozen and carried along by
// the steady wind — Taylor's hypothesis — so it looks like gusts sweeping through the rain).
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>

#include "sim/params.h"

namespace raintrace::sim {

/// The paper's eq. 5: w(t) = cos(πt)·cos(3πt)·cos(5πt)·cos(7πt)·(−0.1)·sin(25πt), t in s.
/// Dimensionless, |w| <= 0.1.
double gust_function(double t_s);

class Wind {
 public:
  static constexpr int kModes = 4;

  Wind(const WindParams& params, std::uint64_t seed);

  /// Steady + gust at time t, m/s (the same everywhere).
  [[nodiscard]] glm::dvec3 uniform_at(double t_s) const;
  /// Full wind at a point, m/s (uniform part + turbulence).
  [[nodiscard]] glm::vec3 at(const glm::vec3& p, double t_s) const;
  /// Turbulence alone at a point; the integrator adds it only when has_turbulence().
  [[nodiscard]] glm::vec3 turbulence_at(const glm::vec3& p, double t_s) const;
  [[nodiscard]] bool has_turbulence() const { return m_turbulence; }
  /// Upper bound of the horizontal wind speed anywhere, any time, m/s.
  [[nodiscard]] double max_horizontal_speed() const;

 private:
  WindParams m_params;
  glm::dvec3 m_gust_dir{1.0, 0.0, 0.0};
  bool m_turbulence = false;
  std::array<glm::vec3, kModes> m_k{};    // wave vectors, rad/m
  std::array<glm::vec3, kModes> m_amp{};  // amplitudes ⟂ k, m/s
  std::array<float, kModes> m_phase{};    // rad
};

}  // namespace raintrace::sim
