// Ring ripple model (see ripples.h).
#include "sim/ripples.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sim/splash.h"
#include "sim/terminal_velocity.h"

namespace raintrace::sim {
namespace {

/// Kinematic viscosity of water at 20 °C, m²/s.
constexpr double kKinematicViscosity = kWaterViscosity / kWaterDensity;
/// Packet half-width in wavelengths: two crests and a trough stand out.
constexpr double kPacketWidth = 0.6;
/// The pixel filter's standard deviation, in pixel spans: exp(−(π/s·σ)²/2) = e⁻² at Nyquist.
constexpr double kPixelSigma = 2.0 / std::numbers::pi;
/// The thin film's ripples live h²/ν, kept within [kFilmLifetimeMin, kFilmLifetimeMax] s.
constexpr double kFilmLifetimeMin = 0.02;
constexpr double kFilmLifetimeMax = 0.2;
/// The measured rings' wavenumber, rad/m (0.2 rad/mm), and the share of the drop's kinetic
/// energy they carry, for the larger of the measured drops (ripples.h).
constexpr double kRingWavenumber = 200.0;
constexpr double kRingEnergyShare = 0.01;
constexpr double kRingReferenceDiameter = 2.8e-3;

}  // namespace

double ripple_speed() {
  // dω/dk of ω² = g·k + (σ/ρ)·k³.
  const double k = kRingWavenumber;
  const double capillary = kWaterSurfaceTension / kWaterDensity;
  const double omega = std::sqrt(kGravity * k + capillary * k * k * k);
  return (kGravity + 3.0 * capillary * k * k) / (2.0 * omega);
}

double ripple_wavelength() { return 2.0 * std::numbers::pi / kRingWavenumber; }

double ripple_amplitude_per_diameter() {
  static const double ratio = [] {
    // A ring's energy, twice its potential and surface energy over the packet (∫∫ ρg·h²/2 +
    // σ·|∇h|²/2 dA: the cosine's mean square ½, the Gaussian's ∫ = w·√π), is
    // ½·(ρg + σk²)·a0²·2πr0·w·√π with r0 = D; set it to the measured share of ½·m·v².
    const double d = kRingReferenceDiameter;
    const double w = kPacketWidth * ripple_wavelength();
    const double k = kRingWavenumber;
    const double kinetic = 0.5 * kWaterDensity * std::numbers::pi / 6.0 * d * d * d *
                           std::pow(terminal_velocity(d), 2.0);
    const double per_square_amplitude =
        0.5 * (kWaterDensity * kGravity + kWaterSurfaceTension * k * k) * 2.0 * std::numbers::pi *
        d * w * std::sqrt(std::numbers::pi);
    return std::sqrt(kRingEnergyShare * kinetic / per_square_amplitude) / d;
  }();
  return ratio;
}

Ripple make_ripple(const glm::vec3& position, float diameter_m, double age_s, double water_depth_m,
                   bool on_puddle, double puddle_lifetime_s) {
  Ripple r;
  r.x = position.x;
  r.z = position.z;
  r.age_s = static_cast<float>(age_s);
  r.on_puddle = on_puddle;
  double lifetime = puddle_lifetime_s;
  double amplitude = ripple_amplitude_per_diameter() * diameter_m;
  if (!on_puddle) {
    lifetime = std::clamp(water_depth_m * water_depth_m / kKinematicViscosity, kFilmLifetimeMin,
                          kFilmLifetimeMax);
    amplitude = std::min(amplitude, 0.5 * water_depth_m);
  }
  if (!(age_s >= 0.0) || age_s >= lifetime || !(amplitude > 0.0)) return r;
  r.lifetime_s = static_cast<float>(lifetime);
  r.amplitude_m = static_cast<float>(amplitude);
  // The ring starts at the crater's edge, about a drop diameter out.
  r.start_radius_m = diameter_m;
  return r;
}

double ripple_slope_rms(double rate_mm_per_h, double lifetime_s) {
  const double k = 2.0 * std::numbers::pi / ripple_wavelength();
  const double w = kPacketWidth * ripple_wavelength();
  const double alpha = ripple_amplitude_per_diameter();
  const double water_m_per_s = rate_mm_per_h * 1e-3 / 3600.0;
  const double mean_square = std::pow(std::numbers::pi, 1.5) * k * k * alpha * alpha * w *
                             lifetime_s / 5.0 * (6.0 / std::numbers::pi) * water_m_per_s;
  return std::sqrt(mean_square);
}

double stirred_radius(const Ripple& ripple) {
  return ripple.start_radius_m + ripple_speed() * ripple.age_s + kPacketWidth * ripple_wavelength();
}

double film_stir(const Ripple& ripple) {
  if (!(ripple.lifetime_s > 0.0f)) return 0.0;
  const double fade = 1.0 - ripple.age_s / ripple.lifetime_s;
  return fade * fade;
}

double ripple_reach(const Ripple& ripple) {
  const double front = ripple.start_radius_m + ripple_speed() * ripple.age_s;
  return front + 3.0 * kPacketWidth * ripple_wavelength();
}

RippleRing::RippleRing(const Ripple& ripple) : m_x(ripple.x), m_z(ripple.z) {
  if (!(ripple.lifetime_s > 0.0f)) return;
  const double t = ripple.age_s;
  m_front = ripple.start_radius_m + ripple_speed() * t;
  const double fade = 1.0 - t / ripple.lifetime_s;
  m_amplitude = ripple.amplitude_m * std::sqrt(ripple.start_radius_m / m_front) * fade * fade;
}

bool RippleRing::point(double x, double z, const PixelSpan& span, Point& p) const {
  if (m_amplitude == 0.0) return false;
  p.dx = x - m_x;
  p.dz = z - m_z;
  p.r = std::sqrt(p.dx * p.dx + p.dz * p.dz);
  p.xi = p.r - m_front;
  const double w = kPacketWidth * ripple_wavelength();
  // Outside the packet first: most points a ring's bounding box asks about are (povgen draws
  // every pixel of it), and the exponential below is most of the cost.
  if (std::abs(p.xi) > 3.0 * w) return false;
  const double k = 2.0 * std::numbers::pi / ripple_wavelength();
  // cos θ between the radius (the wave's direction here) and the line of sight.
  const double cos_t = p.r > 1e-9 ? (p.dx * span.dir_x + p.dz * span.dir_z) / p.r : 1.0;
  const double sigma2 = kPixelSigma * kPixelSigma *
                        (span.along_m * span.along_m * cos_t * cos_t +
                         span.across_m * span.across_m * (1.0 - cos_t * cos_t));
  // The pixel filter exp(−k²σ²/2) and the packet's envelope exp(−ξ²/(2w²)) in one exponential.
  p.gain = m_amplitude * std::exp(-0.5 * (k * k * sigma2 + p.xi * p.xi / (w * w)));
  return p.gain != 0.0;
}

double RippleRing::height_at(double x, double z, const PixelSpan& span) const {
  Point p;
  if (!point(x, z, span, p)) return 0.0;
  const double k = 2.0 * std::numbers::pi / ripple_wavelength();
  return p.gain * std::cos(k * p.xi);
}

RippleSample RippleRing::sample_at(double x, double z, const PixelSpan& span) const {
  RippleSample s;
  Point p;
  if (!point(x, z, span, p)) return s;
  const double k = 2.0 * std::numbers::pi / ripple_wavelength();
  const double w = kPacketWidth * ripple_wavelength();
  const double c = std::cos(k * p.xi), sn = std::sin(k * p.xi);
  s.height = p.gain * c;
  // d/dr of envelope·cos(kξ) = envelope·(−ξ/w²·cos − k·sin).
  const double dh_dr = p.gain * (-p.xi / (w * w) * c - k * sn);
  if (p.r > 1e-9) {
    s.slope_x = dh_dr * p.dx / p.r;
    s.slope_z = dh_dr * p.dz / p.r;
  }
  return s;
}

RippleSample ripple_at(const Ripple& ripple, double x, double z, const PixelSpan& span) {
  return RippleRing(ripple).sample_at(x, z, span);
}

}  // namespace raintrace::sim
