// Wind field: steady vector + the paper's gust function w(t) (eq. 5) + optional smooth,
// divergence-free spatial turbulence (a few seeded Fourier modes, frozen and carried along by
// the steady wind — Taylor's hypothesis — so it looks like gusts sweeping through the rain).
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>

#include "sim/params.h"

namespace raintrace::sim {

/// sin(x), within 2e-7 of std::sin for |x| < 100, in plain float arithmetic (one reduction by π,
/// then the odd Taylor polynomial to x¹¹) so that loops calling it
/// vectorise; the integrator evaluates turbulence with it for every drop and substep.
inline float sin_approx(float x) {
  // Nearest multiple of π (conversion truncates toward zero, hence the signed half).
  const int n = static_cast<int>(x * 0.318309886f + (x >= 0.0f ? 0.5f : -0.5f));
  const auto fn = static_cast<float>(n);
  // π in three parts (Cody-Waite) so that x − n·π is exact enough for large n.
  float r = x - fn * 3.140625f;
  r -= fn * 9.67502593994140625e-4f;
  r -= fn * 1.509957990978376432e-7f;
  const float r2 = r * r;
  const float p =
      r + r * r2 *
              (-1.0f / 6.0f +
               r2 * (1.0f / 120.0f + r2 * (-1.0f / 5040.0f +
                                           r2 * (1.0f / 362880.0f + r2 * (-1.0f / 39916800.0f)))));
  // sin(r + nπ) = (−1)ⁿ·sin(r).
  return (n & 1) != 0 ? -p : p;
}

/// The paper's eq. 5: w(t) = cos(πt)·cos(3πt)·cos(5πt)·cos(7πt)·(−0.1)·sin(25πt), t in s.
/// Dimensionless, |w| <= 0.1, periodic with period 2 s (every factor repeats after 2 s).
double gust_function(double t_s);

/// The period of gust_function() as printed, s.
inline constexpr double kGustFunctionPeriodS = 2.0;

class Wind {
 public:
  static constexpr int kModes = 4;

  /// The turbulence's Fourier modes: T(p, t) = Σ amp·sin(k·(p − drift·t) + phase).
  struct Modes {
    std::array<glm::vec3, kModes> k{};    ///< wave vectors, rad/m
    std::array<glm::vec3, kModes> amp{};  ///< amplitudes ⟂ k, m/s
    std::array<float, kModes> phase{};    ///< rad
    glm::dvec3 drift{0.0};                ///< the steady wind that carries the pattern, m/s
  };

  Wind(const WindParams& params, std::uint64_t seed);

  /// Steady + gust at time t, m/s (the same everywhere). The gust is
  /// gust_strength·w(t·kGustFunctionPeriodS / gust_period_s) along gust_direction.
  [[nodiscard]] glm::dvec3 uniform_at(double t_s) const;
  /// Full wind at a point, m/s (uniform part + turbulence).
  [[nodiscard]] glm::vec3 at(const glm::vec3& p, double t_s) const;
  /// Turbulence alone at a point; the integrator adds it only when has_turbulence().
  [[nodiscard]] glm::vec3 turbulence_at(const glm::vec3& p, double t_s) const;
  [[nodiscard]] bool has_turbulence() const { return m_turbulence; }
  [[nodiscard]] const Modes& modes() const { return m_modes; }
  /// Upper bound of the horizontal wind speed anywhere, any time, m/s.
  [[nodiscard]] double max_horizontal_speed() const;
  /// Lipschitz constant of the turbulence: |T(p) − T(q)| <= L·|p − q| at any time, 1/s
  /// (0 without turbulence).
  [[nodiscard]] double turbulence_lipschitz_per_s() const;

 private:
  WindParams m_params;
  glm::dvec3 m_gust_dir{1.0, 0.0, 0.0};
  bool m_turbulence = false;
  Modes m_modes;
};

}  // namespace raintrace::sim
