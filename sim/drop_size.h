// Raindrop size distribution: Marshall-Palmer N(D) = N0·e^(−ΛD) (N0 = 8000 m⁻³mm⁻¹,
// Λ = 4.1·R^−0.21 mm⁻¹) or uniform, truncated to [Dmin, Dmax]. The analytic functions give the
// textbook moments; DropSizeModel is what the World draws from.
#pragma once

#include <vector>

#include "sim/params.h"

namespace raintrace::sim {

/// Marshall-Palmer's intercept N0, m⁻³ mm⁻¹.
inline constexpr double kMarshallPalmerN0 = 8000.0;

/// Λ = 4.1·R^−0.21, mm⁻¹, for a rain rate R > 0 in mm/h.
double marshall_palmer_lambda_per_mm(double rate_mm_per_h);
/// ∫ N0·e^(−ΛD) dD over [dmin, dmax] mm: drops per m³.
double marshall_palmer_number_density(double rate_mm_per_h, double dmin_mm, double dmax_mm);
/// Mean diameter of the truncated distribution, mm (1/Λ when untruncated).
double marshall_palmer_mean_diameter_mm(double rate_mm_per_h, double dmin_mm, double dmax_mm);
/// Extinction coefficient of Marshall-Palmer rain, 1/m: ∫ N(D)·Q·πD²/4 dD over [dmin, dmax] mm
/// with the extinction efficiency Q = 2 of drops much larger than the wavelength (geometric
/// shadow + diffraction). Untruncated: N0·π·Q/(2Λ³) — 1.0e-3 /m at 5 mm/h.
double marshall_palmer_extinction_per_m(double rate_mm_per_h, double dmin_mm, double dmax_mm);
/// Liquid water content ρ_w·∫ (π/6)·D³·N(D) dD over [dmin, dmax], g/m³ (untruncated: π·N0·ρ/Λ⁴,
/// ≈ 0.089·R^0.84).
double marshall_palmer_water_content(double rate_mm_per_h, double dmin_mm, double dmax_mm);

/// The configured distribution, tabulated for sampling, with its concentration scaled so that
/// drops falling at terminal velocity carry exactly the configured rain rate to the ground.
/// Why scaled: Marshall-Palmer's N0 with measured fall speeds gives the rate only within
/// ~20 % (and truncation shifts it more); the spec asks for the rate at the ground, so the
/// shape (Λ) is kept and N0 rescaled. concentration_scale() reports the factor.
class DropSizeModel {
 public:
  /// rain.rate_mm_per_h may be 0 (no drops). Expects diameter_min_mm <= diameter_max_mm.
  explicit DropSizeModel(const RainParams& rain);

  /// Drops per m³ in steady rain.
  [[nodiscard]] double number_density_per_m3() const { return m_number_density; }
  /// Drops crossing a horizontal plane per m² per s (∫ N(D)·v(D) dD).
  [[nodiscard]] double number_flux_per_m2_s() const { return m_number_flux; }
  /// Geometric cross-section of the drops per m³ of air, ∫ N(D)·πD²/4 dD, m²/m³ = 1/m: the
  /// share of a line of sight's length that drops cover, per metre (the rain's optical depth
  /// per metre in geometric optics, without diffraction).
  [[nodiscard]] double cross_section_per_m() const { return m_cross_section_per_m; }
  /// Mean diameter of drops in the air, m.
  [[nodiscard]] double mean_diameter_m() const { return m_mean_diameter_m; }
  /// Applied N0 / Marshall-Palmer N0 (for uniform: drops per m³ per mm of width).
  [[nodiscard]] double concentration_scale() const { return m_scale; }
  /// Diameter (m) of a drop in the air, u uniform in [0, 1).
  [[nodiscard]] double sample_in_air(double u) const;
  /// Diameter (m) of a drop crossing a horizontal plane (weighted by fall speed), u in [0, 1).
  [[nodiscard]] double sample_in_flux(double u) const;

 private:
  [[nodiscard]] double invert(const std::vector<double>& cdf, double u) const;

  double m_dmin_mm = 0.0;
  double m_step_mm = 0.0;
  std::vector<double> m_cdf_air;  // unnormalised cumulative, per grid point
  std::vector<double> m_cdf_flux;
  double m_number_density = 0.0;
  double m_number_flux = 0.0;
  double m_mean_diameter_m = 0.0;
  double m_cross_section_per_m = 0.0;
  double m_scale = 0.0;
};

}  // namespace raintrace::sim
