// Terminal fall speed of a raindrop by diameter, and the quadratic drag coefficient that makes
// the integrator converge to it. Gunn & Kinzer (1949) measured the speeds; Atlas et al. (1973)
// fitted v = 9.65 − 10.3·e^(−0.6·D[mm]) m/s, good within a few % above 0.5 mm.
#pragma once

namespace raintrace::sim {

/// Standard gravity, m/s².
inline constexpr double kGravity = 9.80665;

/// Terminal velocity in still air at sea level, m/s, for an equivalent diameter in metres.
/// Atlas et al. (1973) for D >= 0.5 mm; below, where that fit turns negative, a line through
/// Gunn & Kinzer's 0.1 mm point (0.27 m/s) meeting the fit at 0.5 mm, and Stokes' v ∝ D²
/// below 0.1 mm. Continuous and increasing; 0 for D <= 0.
double terminal_velocity(double diameter_m);

/// Drag coefficient k, 1/m, in a = g + k·|u|·u (u = wind − velocity): at terminal velocity
/// drag balances gravity, k·v_t² = g, so k = g / v_t².
double drag_coefficient(double diameter_m);

}  // namespace raintrace::sim
