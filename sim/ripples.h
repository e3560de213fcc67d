// Ring ripples from drop impacts on standing water, as a height field over the ground.
//
// A drop hitting water sends out a packet of capillary-gravity waves, ω² = g·k + (σ/ρ)·k³.
// Raindrop rings are measured at a steady wavenumber of 0.2 rad/mm (λ ≈ 31 mm) for 2.2 and
// 2.8 mm drops, carrying about 1 % of the drop's kinetic energy (IEEE J. Oceanic Eng. 24(3),
// 323–332, 1999); theory puts the prevailing waves near the group velocity's minimum, 0.178 m/s
// at λ ≈ 45 mm (Le Méhauté 1988, J. Fluid Mech. 197). The model draws that measured ring:
// h(r, t) = a(t)·exp(−ξ²/(2w²))·cos(k·ξ), ξ = r − r_f(t), r_f = r0 + c_g·t, with k = 0.2 rad/mm,
// c_g = dω/dk there (0.184 m/s: the packet, where the energy is, travels at the group velocity)
// and w = 0.6·λ (two crests and a trough). The crests ride with the packet: the faster phase
// speed (0.25 m/s) would move them through it, a detail no pixel shows. The amplitude spreads
// with the ring, a ∝ √(r0/r_f) (energy conserved on a circle), starts at
// a0 = ripple_amplitude_per_diameter()·D and fades to 0 by the ripple's lifetime with (1 − t/T)².
// T is ripples.lifetime_s on a puddle (about half a second: viscous and bottom damping of
// a 3 cm wave are slower, ~2 s for a 5 mm puddle, but the spreading ring has fallen below what
// a reflection shows by then); on the thin film outside puddles the bottom stops the wave
// within T = h²/ν (0.09 s for 0.3 mm), and the film caps the amplitude at half its depth.
//
// Seen from a camera, a pixel averages the ring over the ground it spans: s_c across the line of
// sight, s_a along it (longer: the ground is seen at a slant). The oscillating part is
// attenuated by exp(−k²·(σ_a²·cos²θ + σ_c²·sin²θ)/2), θ between the ring's radius and the line of
// sight, σ = 0.64 of the span: a Gaussian that takes a wave at the pixel grid's Nyquist limit
// (two pixels a wavelength) down to e⁻² keeps it from aliasing into blotches, and rings fade out
// smoothly with distance, first where the slant squeezes them.
#pragma once

#include "sim/frame.h"

namespace raintrace::sim {

/// The measured ring: its spreading speed (the group velocity at its wavenumber, m/s) and its
/// wavelength (m), for water at 20 °C.
double ripple_speed();
double ripple_wavelength();

/// First crest height per metre of drop diameter, such that a 2.8 mm drop at its terminal speed
/// puts 1 % of its kinetic energy into the ring, as measured: 0.34 (a 2 mm drop's first crest
/// 0.7 mm). One ratio for every size keeps the roughness in closed form (ripple_slope_rms()); the
/// share then goes as 1/v(D)²: 2 % for a 1.5 mm drop, 0.8 % for a 4 mm one.
double ripple_amplitude_per_diameter();

/// The ripple of one impact `age_s` after it, or a ripple with lifetime 0 when it has faded
/// (age >= lifetime) or makes none. water_depth_m: puddle depth or film thickness;
/// puddle_lifetime_s: ripples.lifetime_s; on_puddle: rings of ripples.lifetime_s, otherwise the
/// film's short ones.
Ripple make_ripple(const glm::vec3& position, float diameter_m, double age_s, double water_depth_m,
                   bool on_puddle, double puddle_lifetime_s);

/// The ground one pixel spans: across_m across the line of sight, along_m along its horizontal
/// direction (dir_x, dir_z), a unit vector. Zero spans: no filtering.
struct PixelSpan {
  double across_m = 0.0;
  double along_m = 0.0;
  double dir_x = 0.0, dir_z = 1.0;
};

/// Height (m) and its gradient (dh/dx, dh/dz) of one ripple at ground point (x, z), as a
/// pixel spanning `span` there sees it (filtered as above).
struct RippleSample {
  double height = 0.0;
  double slope_x = 0.0;
  double slope_z = 0.0;
};
RippleSample ripple_at(const Ripple& ripple, double x, double z, const PixelSpan& span = {});

/// One ripple at its age, with what all of its points share worked out once: a ring map asks
/// for thousands of points of each ring, and ripple_at() would redo that for every one.
class RippleRing {
 public:
  explicit RippleRing(const Ripple& ripple);
  /// ripple_at(ripple, x, z, span).height.
  [[nodiscard]] double height_at(double x, double z, const PixelSpan& span) const;
  /// ripple_at(ripple, x, z, span).
  [[nodiscard]] RippleSample sample_at(double x, double z, const PixelSpan& span) const;

 private:
  /// The wave at (x, z): ξ (m from the front), the packet's height scale there including the
  /// pixel filter, and the offset from the centre. False outside the packet (flat there).
  struct Point {
    double xi = 0.0, gain = 0.0, dx = 0.0, dz = 0.0, r = 0.0;
  };
  bool point(double x, double z, const PixelSpan& span, Point& p) const;

  float m_x = 0.0f, m_z = 0.0f;
  double m_front = 0.0;      ///< radius of the packet's centre, m
  double m_amplitude = 0.0;  ///< crest height before the pixel filter, m (0: flat)
};

/// Largest distance from its centre at which the ripple is not flat (m).
double ripple_reach(const Ripple& ripple);

/// A film ripple as a stirred patch: within radius stirred_radius() of the impact (the ring's
/// front plus a packet width) the film is disturbed with strength film_stir() — 1 when fresh,
/// fading with the ring as (1 − t/T)². The renderer darkens the film's reflection by it,
/// spread over a pixel where the patch is smaller than one: it stays an effect of the impact's
/// place and time, never a ring smoothed to nothing.
double stirred_radius(const Ripple& ripple);
double film_stir(const Ripple& ripple);

/// Root-mean-square slope of standing water under rain of `rate_mm_per_h` whose rings last
/// `lifetime_s`: the roughness of a puddle seen from too far for its rings to be drawn.
/// Each ring contributes ∫∫ ½·(k·a(t)·envelope)² dA dt = π^{3/2}·k²·a0²·r0·w·T/5 with
/// a0 = αD, r0 = D (∝ D³), so summed over the rain's drops per m² and s, whatever their sizes,
/// the mean square slope is π^{3/2}·k²·α²·w·T/5 · (6/π)·(rain rate in m/s): D³ summed over the
/// flux is 6/π times the water volume falling per m² and s. 5 mm/h, 0.5 s: 0.0114.
double ripple_slope_rms(double rate_mm_per_h, double lifetime_s);

}  // namespace raintrace::sim
