// Impacts on the visible ground (see ground_impacts.h).
#include "sim/ground_impacts.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "sim/random.h"
#include "sim/terminal_velocity.h"
#include "sim/view_volume.h"

namespace raintrace::sim {
namespace {

/// Below this mean a Poisson count is drawn by inversion, above by its normal approximation
/// (relative error of the variance under 1 %).
constexpr double kPoissonExact = 50.0;

std::uint64_t cell_key(std::int32_t ix, std::int32_t iz) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(ix)) << 32) |
         static_cast<std::uint32_t>(iz);
}

/// Poisson count with mean lambda from independent uniforms u1, u2.
std::uint64_t poisson(double lambda, double u1, double u2) {
  if (lambda <= 0.0) return 0;
  if (lambda < kPoissonExact) {
    double p = std::exp(-lambda), cdf = p;
    std::uint64_t k = 0;
    while (u1 > cdf && p > 0.0) {
      ++k;
      p *= lambda / static_cast<double>(k);
      cdf += p;
    }
    return k;
  }
  const double normal =
      std::sqrt(-2.0 * std::log(1.0 - u1)) * std::cos(2.0 * std::numbers::pi * u2);
  return static_cast<std::uint64_t>(std::max(0.0, std::round(lambda + std::sqrt(lambda) * normal)));
}

}  // namespace

GroundDetail::GroundDetail(const Camera& camera)
    : m_eye(camera.position),
      m_pixel_angle(2.0 * std::tan(camera.fov_deg * std::numbers::pi / 360.0) /
                    std::max(1, camera.width_px)) {}

double GroundDetail::pixel_m(const glm::dvec3& p) const {
  return glm::length(p - m_eye) * m_pixel_angle;
}

double GroundDetail::keep(const glm::dvec3& p) const {
  const double ratio = kDetailPixel_m / std::max(pixel_m(p), 1e-12);
  return std::min(1.0, ratio * ratio);
}

ImpactSampler::ImpactSampler(const Camera& camera, double ground_y, const DropSizeModel& sizes,
                             const SpawnRegion& region, const GroundDetail& detail,
                             std::uint64_t seed)
    : m_region(region),
      m_detail(detail),
      m_sizes(sizes),
      m_seed(seed),
      m_ground(ground_y),
      m_eye(camera.position) {
  const ViewVolume view(camera, 1e-3, kMaxDistance_m);
  const double tan_h = std::tan(camera.fov_deg * std::numbers::pi / 360.0);
  const double tan_v = tan_h / camera.aspect;
  // (p − eye)·(F·tan ∓ side) >= 0 on the inner side of each of the four planes.
  for (const double sign : {-1.0, 1.0}) {
    m_planes.push_back(view.forward() * tan_h + sign * view.right());
    m_planes.push_back(view.forward() * tan_v + sign * view.up());
  }
  if (m_eye.y <= m_ground) return;  // under the ground: none of it is seen from above
  const auto reach = static_cast<std::int32_t>(std::ceil(kMaxDistance_m / kCell_m));
  const auto ex = static_cast<std::int32_t>(std::floor(m_eye.x / kCell_m));
  const auto ez = static_cast<std::int32_t>(std::floor(m_eye.z / kCell_m));
  for (std::int32_t ix = ex - reach; ix <= ex + reach; ++ix) {
    for (std::int32_t iz = ez - reach; iz <= ez + reach; ++iz) {
      const double x0 = ix * kCell_m, z0 = iz * kCell_m;
      const double cx = std::clamp(m_eye.x, x0, x0 + kCell_m);
      const double cz = std::clamp(m_eye.z, z0, z0 + kCell_m);
      const double dx = cx - m_eye.x, dz = cz - m_eye.z;
      if (dx * dx + dz * dz > kMaxDistance_m * kMaxDistance_m || !visible(x0, z0)) continue;
      // The footprint is a rectangle in the camera's yaw frame: a cell is inside it when all
      // four corners are.
      int inside = 0;
      for (const double x : {x0, x0 + kCell_m}) {
        for (const double z : {z0, z0 + kCell_m}) {
          inside += m_region.in_measure_area({x, m_ground, z}) ? 1 : 0;
        }
      }
      Cell cell;
      cell.ix = ix;
      cell.iz = iz;
      cell.keep_max = m_detail.keep({cx, m_ground, cz});
      cell.touches_footprint = inside > 0;
      cell.inside_footprint = inside == 4;
      m_cells.push_back(cell);
      if (!cell.inside_footprint) m_area_m2 += kCell_m * kCell_m;
    }
  }
}

bool ImpactSampler::visible(double x0, double z0) const {
  for (const glm::dvec3& n : m_planes) {
    bool any = false;
    for (const double x : {x0, x0 + kCell_m}) {
      for (const double z : {z0, z0 + kCell_m}) {
        for (const double y : {m_ground, m_ground + kReach_m}) {
          any = any || glm::dot(glm::dvec3{x, y, z} - m_eye, n) >= 0.0;
        }
      }
    }
    if (!any) return false;
  }
  return true;
}

void ImpactSampler::sample(std::int64_t slot, const glm::dvec3& wind,
                           std::vector<GroundImpact>& out, double volume_start_s) const {
  const double flux = m_sizes.number_flux_per_m2_s();
  if (!(flux > 0.0)) return;
  const auto slot_bits = static_cast<std::uint64_t>(slot);
  const bool volume_runs = static_cast<double>(slot) * kSlot_s >= volume_start_s;
  for (const Cell& cell : m_cells) {
    if (cell.inside_footprint && volume_runs) continue;
    const std::uint64_t key = cell_key(cell.ix, cell.iz);
    const double mean = flux * kCell_m * kCell_m * kSlot_s * cell.keep_max;
    const std::uint64_t n = poisson(mean, uniform(m_seed, Stream::ground_count, key, 2 * slot_bits),
                                    uniform(m_seed, Stream::ground_count, key, 2 * slot_bits + 1));
    for (std::uint64_t k = 0; k < n; ++k) {
      const std::uint64_t base = (slot_bits << 20) ^ (k << 4);
      auto u = [&](std::uint64_t dim) {
        return uniform(m_seed, Stream::ground_impact, key, base | dim);
      };
      const glm::dvec3 p{(cell.ix + u(0)) * kCell_m, m_ground, (cell.iz + u(1)) * kCell_m};
      // Thinned from the cell's largest keep() to this point's: kept with keep(p) overall.
      const double keep = m_detail.keep(p);
      if (u(2) * cell.keep_max >= keep) continue;
      const double t = (static_cast<double>(slot) + u(4)) * kSlot_s;
      if (cell.touches_footprint && t >= volume_start_s && m_region.in_measure_area(p)) continue;
      const double d = m_sizes.sample_in_flux(u(3));
      GroundImpact impact;
      impact.key = hash_key(m_seed, Stream::ground_impact, key, base | 15) | (1ULL << 63);
      impact.time_s = t;
      impact.position = glm::vec3(p);
      impact.velocity =
          glm::vec3(static_cast<float>(wind.x), -static_cast<float>(terminal_velocity(d)),
                    static_cast<float>(wind.z));
      impact.diameter_m = static_cast<float>(d);
      impact.weight = static_cast<float>(1.0 / keep);
      out.push_back(impact);
    }
  }
}

}  // namespace raintrace::sim
