// How one raindrop scatters light, by geometric optics: the light a falling drop sends toward
// the camera, which sets the brightness of rain streaks and of the rain medium beyond far_m.
// A drop much larger than the wavelength refracts and reflects like a glass bead (van de Hulst
// 1957, "Light scattering by small particles", ch. 12): a ray entering at incidence i leaves
// after p internal passes, deviated by (p − 1)·π + 2i − 2p·r (r the refraction angle), carrying
// the Fresnel share of its energy. Diffraction sends as much energy again into a cone of
// ~λ/D ≈ 0.03° around the forward direction: for images it stays inside the pixel (see
// rain_medium.h). Pure functions, no I/O.
#pragma once

#include <vector>

namespace raintrace::sim {

/// Refractive index of water for visible light (20 °C, 589 nm: 1.333).
inline constexpr double kWaterIor = 1.333;

/// A drop's geometric-optics scattering (no diffraction, no absorption).
struct DropScattering {
  /// Phase function P(θ) in 1° bins, bin k = [k°, k + 1°), k = 0…179, normalised so that
  /// ∫ P dΩ / 4π = 1 (an isotropic scatterer has P = 1 everywhere).
  std::vector<double> phase;
  /// Mean cosine of the scattering angle, g = ∫ P cos θ dΩ / 4π.
  double asymmetry = 0.0;
  /// Share of the scattered light leaving within 90° of forward (θ < 90°).
  double forward_share = 0.0;
  /// Mean cosine of θ over the light scattered forward (θ < 90°).
  double forward_mean_cosine = 0.0;
};

/// Traces `rays` parallel rays, uniform over the drop's cross-section, through a sphere of
/// relative index `ior`, following each to 9 internal reflections (what is left after them
/// is < 1e-9 of the light), unpolarised light (the mean of the s and p Fresnel shares).
DropScattering drop_scattering(double ior = kWaterIor, int rays = 200000);

/// drop_scattering() of water with 20 000 rays (g to 1e-4), traced once per process (~10 ms).
const DropScattering& water_drop_scattering();

/// POV-Ray's finish for a flat patch facing the camera, standing in for a drop:
/// `diffuse front, back` with `brilliance b` gives front·|cos θ|^b for a light on the camera's
/// side and back·|cos θ|^b for one behind the drop (POV-Ray 3.7's backside diffuse), where θ
/// is the angle between the patch's normal and the light. With the normal toward the camera,
/// that is the scattering angle's cosine. POV-Ray shows a white patch with diffuse 1 facing a
/// light of colour C as radiance C, i.e. C = E/π for the irradiance E, while a drop's mean
/// radiance over its cross-section is E·P(θ)/4π = C·P(θ)/4: so each lobe is P/4.
struct PovrayLobes {
  double brilliance = 1.0;  ///< exponent b of |cos θ|
  double back = 0.0;        ///< diffuse of the back side: light from behind the drop
  double front = 0.0;       ///< diffuse of the front side: light from the camera's side
};

/// Fits the lobes to a drop's scattering: b so that A·cos^b θ has the forward light's mean
/// cosine ((b + 1)/(b + 2) = forward_mean_cosine), A so that it carries the forward share
/// (A/(2(b + 1)) = forward_share), and the front lobe, with the same b, the backward share.
PovrayLobes fit_povray_lobes(const DropScattering& scattering);

}  // namespace raintrace::sim
