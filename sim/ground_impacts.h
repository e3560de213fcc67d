// Drops reaching the visible ground: where and when they land, wherever the camera can see the
// ground, not only under the simulated volume of drops.
//
// The volume of drops ([near_m, far_m] of the view frustum) covers only part of the ground in
// view, and none of it when the camera looks up. Impacts elsewhere are sampled straight from the
// rain's flux: the ground is cut into fixed 1 m cells, time into 50 ms slots, and each visible
// (cell, slot) receives a Poisson number of impacts with mean flux·area·slot, at uniform
// places and times, with diameters from the flux distribution N(D)·v(D) (DropSizeModel::
// sample_in_flux) falling at terminal speed with the wind. Every random number is keyed by
// (seed, cell, slot, impact), so the impacts never depend on thread count, frame rate or
// anything else simulated.
//
// The two sources split the ground without overlap: the volume's drops land where they land
// inside its footprint rectangle (SpawnRegion::in_measure_area, where the volume carries the full
// flux), and sampled impacts falling inside that rectangle are discarded. A drop seen falling
// thus splashes where it lands, once.
//
// Level of detail by size on screen: far away one pixel covers so much ground that its
// impacts are not worth simulating one by one. An impact at a point where a pixel spans s
// metres of ground is kept with probability p = min(1, (kDetailPixel_m / s)²) — every impact
// where ripple rings are still resolved, then fewer in proportion to the ground a pixel covers,
// so the kept impacts per pixel stay about constant — and carries weight 1/p, which the
// renderer turns into light (a kept splash stands for 1/p splashes). Which impacts survive is
// keyed like the rest, so thinning out with distance is smooth and steady from frame to frame.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "sim/camera.h"
#include "sim/drop_size.h"
#include "sim/spawn_region.h"
#include "sim/splash.h"

namespace raintrace::sim {

/// One drop reaching the ground.
struct GroundImpact {
  /// The drop's id for drops of the volume; a hash with the top bit set for sampled impacts.
  std::uint64_t key = 0;
  double time_s = 0.0;       ///< simulated time of the impact
  glm::vec3 position{0.0f};  ///< m, on the ground
  glm::vec3 velocity{0.0f};  ///< m/s at impact
  float diameter_m = 0.0f;
  float weight = 1.0f;  ///< 1 / the probability the level of detail kept it, >= 1
  // Filled in by the World when it records the impact:
  float water_depth_m = 0.0f;  ///< puddle or film depth where it landed
  bool on_puddle = false;      ///< landed in a puddle
  CrownSplash crown;           ///< its splash (no droplets below the threshold)
};

/// Level of detail of ground effects by the size of a pixel on the ground.
class GroundDetail {
 public:
  /// Full detail while a pixel spans at most this much ground, m: a quarter of a ring's
  /// wavelength, where a pixel keeps 55 % of a ring's height (sim/ripples.h). Beyond, the
  /// thinned rings and the renderer's noise (which grows as the pixel filter takes the rings
  /// away) share the water's roughness.
  static constexpr double kDetailPixel_m = 0.0085;

  explicit GroundDetail(const Camera& camera);

  /// Metres of ground (or anything) one pixel spans at point p: distance × pixel angle.
  [[nodiscard]] double pixel_m(const glm::dvec3& p) const;
  /// Probability an impact at p is simulated, in (0, 1].
  [[nodiscard]] double keep(const glm::dvec3& p) const;

 private:
  glm::dvec3 m_eye{};
  double m_pixel_angle = 0.0;  ///< radians per pixel at the centre of the image
};

/// Samples impacts on the visible ground outside the simulated volume's footprint.
class ImpactSampler {
 public:
  static constexpr double kCell_m = 1.0;
  static constexpr double kSlot_s = 0.05;
  /// Ground farther than this (horizontally from the eye) gets no impacts: a whole splash is
  /// then well under a tenth of a pixel even at 1280 pixels across.
  static constexpr double kMaxDistance_m = 100.0;
  /// How far above the ground splashes and ripples reach, m: a cell whose box up to this
  /// height touches the view is visible.
  static constexpr double kReach_m = 0.3;

  /// region: the simulated volume, whose footprint is left to its own drops.
  ImpactSampler(const Camera& camera, double ground_y, const DropSizeModel& sizes,
                const SpawnRegion& region, const GroundDetail& detail, std::uint64_t seed);

  /// Appends the impacts whose times lie in slot `slot`, [slot, slot + 1)·kSlot_s, in a fixed
  /// order. wind: the horizontal wind the drops fall with (y ignored). Impacts earlier than
  /// volume_start_s land on the footprint too: the volume's drops only land from then on (a
  /// World starts its drops at the beginning of the prewarm, and frame 1 still shows the ripples
  /// of the moments before).
  void sample(std::int64_t slot, const glm::dvec3& wind, std::vector<GroundImpact>& out,
              double volume_start_s = -1e300) const;

  /// Ground area sampled once the volume runs, m² (visible cells, footprint excluded, counted in
  /// whole cells).
  [[nodiscard]] double area_m2() const { return m_area_m2; }
  [[nodiscard]] std::size_t cell_count() const { return m_cells.size(); }

 private:
  struct Cell {
    std::int32_t ix = 0, iz = 0;
    double keep_max = 1.0;  ///< keep() at the cell's nearest point to the eye
    bool touches_footprint = false;
    bool inside_footprint = false;
  };

  [[nodiscard]] bool visible(double x0, double z0) const;

  SpawnRegion m_region;
  GroundDetail m_detail;
  DropSizeModel m_sizes;
  std::uint64_t m_seed;
  double m_ground;
  glm::dvec3 m_eye{};
  std::vector<glm::dvec3> m_planes;  ///< inward normals of the view's four sides
  std::vector<Cell> m_cells;
  double m_area_m2 = 0.0;
};

}  // namespace raintrace::sim
