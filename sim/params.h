// Everything the simulation can be told, one struct per concern, with units, ranges and
// defaults. cli/ fills these from the scene file; nothing here knows about files.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>

#include "sim/camera.h"

namespace raintrace::sim {

enum class DropSizeDistribution {
  marshall_palmer,  ///< N(D) = N0·e^(−ΛD), N0 = 8000 m⁻³mm⁻¹, Λ = 4.1·R^−0.21 mm⁻¹
  uniform,          ///< the paper's choice: uniform in [diameter_min_mm, diameter_max_mm]
};

struct RainParams {
  /// Rain rate at the ground, mm/h, in [0, 500]. Default 5 (moderate rain).
  double rate_mm_per_h = 5.0;
  /// How drop diameters are drawn. Default Marshall-Palmer.
  DropSizeDistribution distribution = DropSizeDistribution::marshall_palmer;
  /// Smallest drop diameter, mm, in [0.1, 8]. Default 0.5.
  double diameter_min_mm = 0.5;
  /// Largest drop diameter, mm, in [diameter_min_mm, 8]. Default 6.
  double diameter_max_mm = 6.0;
  /// Drops are simulated in the camera's frustum from near_m to far_m, metres. Default 0.3.
  double near_m = 0.3;
  /// Far end of the simulated frustum, metres, in (near_m, 1000]; beyond it fog/mist stands
  /// for the rain. Default 12.
  double far_m = 12.0;
  /// Height of the spawn ceiling above the highest point of the view volume, metres, >= 0.
  /// Default 2 (drops enter the view already at terminal speed).
  double ceiling_margin_m = 2.0;
  /// Merging of drops that meet on the way down (paper §3.3). Default true.
  bool merging = true;
  /// Diameter past which a drop breaks up into smaller ones, mm, in [4, 10]. Default 6.5.
  double breakup_diameter_mm = 6.5;
  /// Rate at which a drop fades (paper's vanishing), 1/s, in [0, 100]. Default 0 (no fading).
  double vanishing_rate_per_s = 0.0;
  /// Linear RGB tint of the water, each in [0, 1]. Default (0.9, 0.95, 1).
  glm::dvec3 colour{0.9, 0.95, 1.0};
};

struct WindParams {
  /// Steady wind velocity, m/s, each component in [-60, 60]. Default (0, 0, 0).
  glm::dvec3 velocity_m_per_s{0.0, 0.0, 0.0};
  /// Add the paper's gust function w(t) (eq. 5). Default false.
  bool gusts = false;
  /// Scale of the gust function, m/s per unit of w(t), in [0, 500]. Default 20.
  double gust_strength = 20.0;
  /// Horizontal direction the gusts push along (normalised; y ignored). Default (1, 0, 0).
  glm::dvec3 gust_direction{1.0, 0.0, 0.0};
  /// Amplitude of smooth spatial turbulence, m/s, in [0, 30]. Default 0 (off).
  double turbulence_m_per_s = 0.0;
  /// Length scale of the turbulence, metres, in [0.1, 100]. Default 4.
  double turbulence_scale_m = 4.0;
};

struct SplashParams {
  /// Drops hitting the ground end in splashes. Default true.
  bool enabled = true;
  /// Droplets per splash, in [0, 32]. Default 4.
  int droplets = 4;
  /// How long splash droplets live, seconds, in (0, 2]. Default 0.15.
  double lifetime_s = 0.15;
};

struct LightningParams {
  /// Lightning on or off. Default false.
  bool enabled = false;
  /// Mean strike rate of the Poisson process, strikes per minute, in [0, 600]. Default 6.
  double strikes_per_minute = 6.0;
  /// L-system generations (trunk = 0, branches, sub-branches…), in [1, 8]. Default 5.
  int generations = 5;
  /// Height of the cloud base where bolts start, metres, in [10, 5000]. Default 300.
  double cloud_height_m = 300.0;
  /// Where strikes land, as seen from the camera: degrees from its horizontal view direction,
  /// positive to the right, in [-180, 180]. The first strike lands exactly there. Default 0.
  double azimuth_deg = 0.0;
  /// Later strikes land within ± this of azimuth_deg (uniformly), degrees, in [0, 180].
  /// Default 25.
  double azimuth_spread_deg = 25.0;
  /// Horizontal distance of the first strike from the camera, metres, in [0, 10000].
  /// Default 400.
  double distance_m = 400.0;
  /// Horizontal distance of later strikes from the camera, metres: [min, max]. Default 80..400.
  double distance_min_m = 80.0;
  double distance_max_m = 400.0;
  /// Radius of the trunk, metres, in (0, 10]. Default 0.6.
  double trunk_radius_m = 0.6;
  /// Return strokes per flash, in [1, 10]. Default 3.
  int return_strokes = 3;
  /// Length of a flash, seconds, in [0.05, 2]. Default 0.35.
  double flash_duration_s = 0.35;
  /// Force a strike at this time, seconds; < 0 means none. Default -1. Lets a short example
  /// show lightning deterministically.
  double first_strike_s = -1.0;
};

struct SimParams {
  Camera camera;
  RainParams rain;
  WindParams wind;
  SplashParams splashes;
  LightningParams lightning;
  /// Height of the ground plane, metres. Default 0.
  double ground_y_m = 0.0;
  /// Integration substep, seconds, in [1e-4, 0.02]. Frames are advanced in whole substeps, so
  /// results do not depend on the frame rate. Default 0.002.
  double substep_s = 0.002;
  /// Simulated time before frame 1 so the volume is already full of falling rain, seconds,
  /// in [0, 60]. Default −1: World picks max(0.2, splashes.lifetime_s + 0.05) — the volume
  /// is filled at steady-state density first, so only splashes and merging need the time.
  double prewarm_s = -1.0;
  /// Worker threads for a step; 0 = all cores. Results never depend on it.
  int threads = 0;
  /// Seed of every random stream. Default 1.
  std::uint64_t seed = 1;
};

}  // namespace raintrace::sim
