// Splash threshold and crown splash (see splash.h for the model and its sources).
#include "sim/splash.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "sim/random.h"
#include "sim/terminal_velocity.h"

namespace raintrace::sim {
namespace {

/// Bai et al.'s proportionality constant between droplet count and (We/We_c − 1).
constexpr double kDropletsPerExcess = 5.0;
/// Share of the drop's speed along the surface that the droplets keep.
constexpr double kTangentialShare = 0.6;
/// Ejection elevation above the surface, radians: uniform in [5°, 50°].
constexpr double kElevationMin = 5.0 * std::numbers::pi / 180.0;
constexpr double kElevationMax = 50.0 * std::numbers::pi / 180.0;
/// Flight integration step, s: a tenth of the drag relaxation time v_t/g of the smallest
/// droplets (~0.1 mm: 22–28 ms), and fixed, so the result does not depend on the frame rate.
constexpr double kFlightStep = 2e-3;

/// Random-number dimensions of an impact (b in Stream::splash): 0 count, 1 mass ratio, and per
/// droplet k the block 8 + 8k.
constexpr std::uint64_t kCountDim = 0;
constexpr std::uint64_t kMassDim = 1;
std::uint64_t droplet_dim(int k, int dim) { return 8 + 8 * static_cast<std::uint64_t>(k) + dim; }

double unit(std::uint64_t seed, std::uint64_t key, std::uint64_t b) {
  return uniform(seed, Stream::splash, key, b);
}

/// Kinetic energy of a drop of diameter D at speed v, J.
double kinetic_energy(double d, double v) {
  return std::numbers::pi / 12.0 * kWaterDensity * d * d * d * v * v;
}

/// Points of the midpoint rule for the mean of m·ln²(D/d) over the droplet distribution.
constexpr int kQuadrature = 64;

/// Diameter of droplet k: the truncated exponential of Bai et al., by inversion.
double droplet_diameter(const CrownSplash& c, double u) {
  const double mean = c.mean_diameter_m;
  const double lo = std::exp(-0.1 * c.max_diameter_m / mean);
  const double hi = std::exp(-c.max_diameter_m / mean);
  return -mean * std::log(lo - u * (lo - hi));
}

}  // namespace

double weber_number(double diameter_m, double normal_speed_m_per_s) {
  return kWaterDensity * diameter_m * normal_speed_m_per_s * normal_speed_m_per_s /
         kWaterSurfaceTension;
}

double ohnesorge_number(double diameter_m) {
  return kWaterViscosity / std::sqrt(kWaterDensity * kWaterSurfaceTension * diameter_m);
}

double splashing_parameter(double diameter_m, double normal_speed_m_per_s) {
  return weber_number(diameter_m, normal_speed_m_per_s) *
         std::pow(ohnesorge_number(diameter_m), -0.4);
}

double critical_splashing_parameter(double water_depth_m, double diameter_m) {
  const double delta = std::clamp(water_depth_m / diameter_m, 0.0, 1.0);
  return kSplashK0 + kSplashKFilm * std::pow(delta, kSplashFilmExponent);
}

bool splashes(double diameter_m, double normal_speed_m_per_s, double water_depth_m) {
  if (!(diameter_m > 0.0)) return false;
  return splashing_parameter(diameter_m, normal_speed_m_per_s) >
         critical_splashing_parameter(water_depth_m, diameter_m);
}

double critical_diameter_at_terminal_speed(double water_depth_m) {
  auto excess = [&](double d) {
    return splashing_parameter(d, terminal_velocity(d)) -
           critical_splashing_parameter(water_depth_m, d);
  };
  double lo = 0.1e-3, hi = 8e-3;
  if (excess(lo) > 0.0) return lo;
  if (excess(hi) <= 0.0) return hi;
  while (hi - lo > 1e-7) {
    const double mid = 0.5 * (lo + hi);
    (excess(mid) > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

CrownSplash crown_splash(const SplashParams& params, const ImpactInput& impact,
                         std::uint64_t seed) {
  CrownSplash c;
  const double d = impact.diameter_m;
  const double vn = std::max(0.0, -static_cast<double>(impact.velocity.y));
  if (!(d > 0.0) || vn <= 0.0) return c;
  const double ratio =
      splashing_parameter(d, vn) / critical_splashing_parameter(impact.water_depth_m, d);
  if (ratio <= 1.0) return c;

  c.expected_droplets = kDropletsPerExcess * (ratio - 1.0);
  c.mass_ratio = 0.2 + 0.9 * unit(seed, impact.key, kMassDim);
  // E[d³] = 6·d̄³ for an exponential distribution: N·6·d̄³ = r·D³ (truncation ignored, as
  // Bai et al. do).
  c.mean_diameter_m = d * std::cbrt(c.mass_ratio / (6.0 * c.expected_droplets));
  c.max_diameter_m = 0.9 * std::cbrt(c.mass_ratio) * d;

  // Energy left for the droplets. Surface energy of the N droplets: N·σ·π·E[d²] with
  // E[d²] = 2·d̄² (exponential), which is what they cost to make.
  const double e_in = kinetic_energy(d, vn);
  const double k_ratio_inverse = 1.0 / ratio;  // = E_k at the threshold / E_k (K ∝ v²)
  const double dissipated = std::max(0.8, k_ratio_inverse) * e_in;
  const double surface_in = kWaterSurfaceTension * std::numbers::pi * d * d;
  const double surface_out = c.expected_droplets * kWaterSurfaceTension * std::numbers::pi * 2.0 *
                             c.mean_diameter_m * c.mean_diameter_m;
  c.kinetic_energy_j = e_in + surface_in - surface_out - dissipated;
  if (c.kinetic_energy_j <= 0.0) {
    c = CrownSplash{};
    return c;
  }
  // u_k = U·ln(D/d_k) with N·E[½·m·u²] = E: U² = 2E / (N·E[m·ln²(D/d)]), the mean taken over
  // the truncated exponential by the midpoint rule (its density ∝ e^(−d/d̄) on [d_min, d_max]).
  const double d_min = 0.1 * c.max_diameter_m, d_max = c.max_diameter_m;
  double weight_sum = 0.0, moment = 0.0;
  for (int i = 0; i < kQuadrature; ++i) {
    const double di = d_min + (i + 0.5) * (d_max - d_min) / kQuadrature;
    const double density = std::exp(-di / c.mean_diameter_m);
    const double log_ratio = std::log(d / di);
    weight_sum += density;
    moment +=
        density * std::numbers::pi / 6.0 * kWaterDensity * di * di * di * log_ratio * log_ratio;
  }
  c.speed_scale = std::sqrt(2.0 * c.kinetic_energy_j / (c.expected_droplets * moment / weight_sum));
  const double drawn = std::floor(c.expected_droplets + unit(seed, impact.key, kCountDim));
  c.droplets = static_cast<int>(std::min<double>(drawn, params.droplets));
  return c;
}

Droplet crown_droplet(const CrownSplash& crown, const ImpactInput& impact, int k,
                      std::uint64_t seed) {
  Droplet out;
  const double d = impact.diameter_m;
  out.diameter_m =
      static_cast<float>(droplet_diameter(crown, unit(seed, impact.key, droplet_dim(k, 0))));
  const double speed = crown.speed_scale * std::log(d / out.diameter_m);
  const double elevation =
      kElevationMin + (kElevationMax - kElevationMin) * unit(seed, impact.key, droplet_dim(k, 1));
  const double azimuth = 2.0 * std::numbers::pi * unit(seed, impact.key, droplet_dim(k, 2));
  const double horizontal = speed * std::cos(elevation);
  out.velocity = glm::vec3(static_cast<float>(horizontal * std::cos(azimuth)),
                           static_cast<float>(speed * std::sin(elevation)),
                           static_cast<float>(horizontal * std::sin(azimuth)));
  out.velocity.x += static_cast<float>(kTangentialShare) * impact.velocity.x;
  out.velocity.z += static_cast<float>(kTangentialShare) * impact.velocity.z;
  return out;
}

void launch_droplets(const CrownSplash& crown, const ImpactInput& impact, double impact_time_s,
                     float weight, double pixel_m, double exposure_s, std::uint64_t seed,
                     std::vector<FlyingDroplet>& out) {
  // The share of a pixel's light one droplet blocks: its width over the pixel's (at most 1),
  // times the share of its streak's pixels it covers in time, d over the streak's length (or
  // over a pixel, for a streak shorter than one). The width alone bounds it: an impact whose
  // largest droplet could not reach the floor throws none worth drawing.
  if (pixel_m > 0.0 && weight * crown.max_diameter_m / pixel_m < kDropletCoverageFloor) return;
  for (int k = 0; k < crown.droplets; ++k) {
    const Droplet drop = crown_droplet(crown, impact, k, seed);
    if (pixel_m > 0.0) {
      const double d = drop.diameter_m;
      const double streak = std::max({glm::length(drop.velocity) * exposure_s, pixel_m, d});
      if (weight * std::min(1.0, d / pixel_m) * (d / streak) < kDropletCoverageFloor) continue;
    }
    FlyingDroplet f;
    f.id = hash_key(seed, Stream::splash, impact.key, droplet_dim(k, 7));
    f.impact_time_s = impact_time_s;
    f.position = impact.position;
    f.velocity = drop.velocity;
    f.wind = glm::vec3(impact.velocity.x, 0.0f, impact.velocity.z);
    f.diameter_m = drop.diameter_m;
    f.drag = static_cast<float>(drag_coefficient(drop.diameter_m));
    f.weight = weight;
    f.ground_y = impact.position.y;
    out.push_back(f);
  }
}

namespace {

glm::vec3 flight_acceleration(const FlyingDroplet& d, const glm::vec3& v) {
  const glm::vec3 u = d.wind - v;
  return glm::vec3{0.0f, -static_cast<float>(kGravity), 0.0f} + d.drag * glm::length(u) * u;
}

/// One midpoint step (second order: 2 ms steps follow the strongly damped start closely).
void flight_step(const FlyingDroplet& d, float dt, glm::vec3& p, glm::vec3& v) {
  const glm::vec3 v_half = v + 0.5f * dt * flight_acceleration(d, v);
  p += dt * v_half;
  v += dt * flight_acceleration(d, v_half);
}

}  // namespace

void fly(FlyingDroplet& droplet, double age_s) {
  const auto target = static_cast<int>(std::floor(age_s / kFlightStep));
  const auto h = static_cast<float>(kFlightStep);
  while (droplet.steps < target && !droplet.landed) {
    flight_step(droplet, h, droplet.position, droplet.velocity);
    ++droplet.steps;
    droplet.landed = droplet.position.y < droplet.ground_y;
  }
}

void add_droplet(const SplashParams& params, const FlyingDroplet& droplet, double age_s,
                 Drops& out) {
  const double lifetime = params.lifetime_s;
  if (droplet.landed || !(age_s >= 0.0) || age_s >= lifetime) return;
  glm::vec3 p = droplet.position, v = droplet.velocity;
  flight_step(droplet, static_cast<float>(age_s - droplet.steps * kFlightStep), p, v);
  if (p.y < droplet.ground_y) return;
  // Fades over the last third of its life (most droplets land long before).
  const double fade = std::clamp(3.0 * (1.0 - age_s / lifetime), 0.0, 1.0);
  out.id.push_back(droplet.id);
  out.position.push_back(p);
  out.velocity.push_back(v);
  out.acceleration.push_back(flight_acceleration(droplet, v));
  out.diameter.push_back(droplet.diameter_m);
  out.age.push_back(static_cast<float>(age_s));
  out.vanishing_rate.push_back(0.0f);
  out.opacity.push_back(static_cast<float>(fade) * droplet.weight);
  out.colour.push_back(glm::vec3(1.0f));
}

void add_splash_droplets(const SplashParams& params, const ImpactInput& impact, double age_s,
                         float weight, double pixel_m, double exposure_s, std::uint64_t seed,
                         Drops& out) {
  std::vector<FlyingDroplet> droplets;
  launch_droplets(crown_splash(params, impact, seed), impact, 0.0, weight, pixel_m, exposure_s,
                  seed, droplets);
  for (FlyingDroplet& d : droplets) {
    fly(d, age_s);
    add_droplet(params, d, age_s, out);
  }
}

}  // namespace raintrace::sim
