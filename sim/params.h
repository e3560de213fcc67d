// Everything the simulation can be told, one struct per concern. Below each struct, its
// parameter table (sim/param_table.h) gives every scene-file key its unit and valid range;
// defaults are the member initialisers. cli/ fills these from the scene file; nothing here
// knows about files.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string_view>
#include <vector>

#include "sim/camera.h"
#include "sim/param_table.h"

namespace raintrace::sim {

enum class DropSizeDistribution {
  marshall_palmer,  ///< N(D) = N0·e^(−ΛD), N0 = 8000 m⁻³mm⁻¹, Λ = 4.1·R^−0.21 mm⁻¹
  uniform,          ///< the paper's choice: uniform in [diameter_min_mm, diameter_max_mm]
};
/// Scene-file names of DropSizeDistribution, in the order of its values.
inline constexpr std::string_view kDropSizeDistributionNames[] = {"marshall-palmer", "uniform"};

struct RainParams {
  /// Rain rate at the ground (moderate rain by default).
  double rate_mm_per_h = 5.0;
  /// How drop diameters are drawn.
  DropSizeDistribution distribution = DropSizeDistribution::marshall_palmer;
  /// Smallest drop diameter.
  double diameter_min_mm = 0.5;
  /// Largest drop diameter.
  double diameter_max_mm = 6.0;
  /// Drops are simulated in the camera's frustum from near_m…
  double near_m = 0.3;
  /// …to far_m; beyond it fog or mist stands for the rain.
  double far_m = 12.0;
  /// Height of the spawn ceiling above the highest point of the view volume, so drops enter
  /// the view already at terminal speed.
  double ceiling_margin_m = 2.0;
  /// Merging of drops that meet on the way down (paper §3.3).
  bool merging = true;
  /// Diameter past which a drop breaks up into smaller ones.
  double breakup_diameter_mm = 6.5;
  /// Rate at which a drop fades (paper's vanishing); 0: no fading.
  double vanishing_rate_per_s = 0.0;
  /// Linear RGB tint of the water.
  glm::dvec3 colour{0.9, 0.95, 1.0};
  /// Beyond far_m, drops are also simulated and drawn within this distance of each lamp of the
  /// environment in view (sim/lamp_rain.h), where the lamp lights them; 0: none.
  double lamp_reach_m = 0.0;
  /// Lamps farther than this from the camera get none (their rain is too fine to show).
  double lamp_far_m = 30.0;
};

/// [rain]
inline constexpr Param<RainParams> kRainParams[] = {
    number("rain", "rate_mm_per_h", &RainParams::rate_mm_per_h, "mm/h", Range::closed(0, 500)),
    choice<&RainParams::distribution>("rain", "distribution", kDropSizeDistributionNames),
    number("rain", "diameter_min_mm", &RainParams::diameter_min_mm, "mm", Range::closed(0.1, 8))
        .at_most("diameter_max_mm"),
    number("rain", "diameter_max_mm", &RainParams::diameter_max_mm, "mm", Range::closed(0.1, 8)),
    number("rain", "near_m", &RainParams::near_m, "m", Range::open(0, 1000)),
    number("rain", "far_m", &RainParams::far_m, "m", Range::open_closed(0, 1000))
        .greater_than("near_m"),
    number("rain", "ceiling_margin_m", &RainParams::ceiling_margin_m, "m", Range::closed(0, 1000)),
    flag("rain", "merging", &RainParams::merging),
    number("rain", "breakup_diameter_mm", &RainParams::breakup_diameter_mm, "mm",
           Range::closed(4, 10)),
    number("rain", "vanishing_rate_per_s", &RainParams::vanishing_rate_per_s, "1/s",
           Range::closed(0, 100)),
    colour("rain", "colour", &RainParams::colour),
    number("rain", "lamp_reach_m", &RainParams::lamp_reach_m, "m", Range::closed(0, 20)),
    number("rain", "lamp_far_m", &RainParams::lamp_far_m, "m", Range::closed(0, 200)),
};
static_assert(well_formed<RainParams>(kRainParams));

struct WindParams {
  /// Steady wind velocity; still air by default.
  glm::dvec3 velocity_m_per_s{0.0, 0.0, 0.0};
  /// Add the paper's gust function w(t) (eq. 5).
  bool gusts = false;
  /// Scale of the gust function, m/s per unit of w(t).
  double gust_strength = 20.0;
  /// Horizontal direction the gusts push along (normalised; y ignored).
  glm::dvec3 gust_direction{1.0, 0.0, 0.0};
  /// Time scale of the gusts: the gust wind at time t is gust_strength·w(2t / gust_period_s),
  /// so one whole pattern of eq. 5 (which repeats every 2 s as printed) takes gust_period_s.
  /// 2 is the paper's equation as printed: a 12.5 Hz flutter that drag filters out of the
  /// drops. The default, 20, swells over 3–20 s with a 0.8 s flutter inside them.
  double gust_period_s = 20.0;
  /// Amplitude (RMS speed) of smooth spatial turbulence; 0: off.
  double turbulence_m_per_s = 0.0;
  /// Length scale of the turbulence.
  double turbulence_scale_m = 4.0;
};

/// [wind]
inline constexpr Param<WindParams> kWindParams[] = {
    vector("wind", "velocity_m_per_s", &WindParams::velocity_m_per_s, "m/s",
           Range::closed(-60, 60)),
    flag("wind", "gusts", &WindParams::gusts),
    number("wind", "gust_strength", &WindParams::gust_strength, "m/s", Range::closed(0, 500)),
    vector("wind", "gust_direction", &WindParams::gust_direction, "", Range::closed(-1000, 1000))
        .with_note("x or z ≠ 0"),
    number("wind", "gust_period_s", &WindParams::gust_period_s, "s", Range::closed(0.1, 600)),
    number("wind", "turbulence_m_per_s", &WindParams::turbulence_m_per_s, "m/s",
           Range::closed(0, 30)),
    number("wind", "turbulence_scale_m", &WindParams::turbulence_scale_m, "m",
           Range::closed(0.1, 100)),
};
static_assert(well_formed<WindParams>(kWindParams));

/// True when a gust direction points somewhere horizontally (x or z not 0; y is ignored).
bool is_horizontal_direction(const glm::dvec3& direction);

struct SplashParams {
  /// Drops that hit the ground hard enough throw crown-splash droplets (sim/splash.h: when
  /// K = We·Oh^−0.4 exceeds 2100 + 5880·(h/D)^1.44).
  bool enabled = true;
  /// Most droplets one splash throws; the crown's own count is 5·(K/K_c − 1), so this only trims
  /// the biggest splashes. 0 draws none (the impacts still ripple).
  int droplets = 32;
  /// Longest a droplet flies before it is dropped; it fades over the last third. Most land
  /// sooner (a 1 mm droplet thrown at 1.5 m/s: 0.1 s).
  double lifetime_s = 0.3;
};

/// [splashes]
inline constexpr Param<SplashParams> kSplashParams[] = {
    flag("splashes", "enabled", &SplashParams::enabled),
    integer("splashes", "droplets", &SplashParams::droplets, "", 0, 64),
    number("splashes", "lifetime_s", &SplashParams::lifetime_s, "s", Range::open_closed(0, 2)),
};
static_assert(well_formed<SplashParams>(kSplashParams));

struct PuddleParams {
  /// Share of the wet ground under standing water. The default, "automatic", is the
  /// environment's: a quarter of night_street's road (cli/scene.cpp), none elsewhere; sim reads
  /// an unresolved value as none.
  double coverage = -1.0;
  /// Typical size of a puddle, across.
  double size_m = 1.2;
  /// Depth of water in the middle of a puddle (from the film at its edge).
  double depth_mm = 6.0;
  /// Depth of the water film on the wet ground between puddles: it sets the splash threshold
  /// there (h/D in K_c).
  double film_mm = 0.3;
  /// Seed of the puddle layout. The puddles belong to the street, not to the rain: `--seed`
  /// changes the rain and leaves them where they are.
  std::uint64_t seed = 1;
};

/// [puddles]
inline constexpr Param<PuddleParams> kPuddleParams[] = {
    number("puddles", "coverage", &PuddleParams::coverage, "", Range::closed(0, 0.9))
        .unset_as("automatic"),
    number("puddles", "size_m", &PuddleParams::size_m, "m", Range::closed(0.1, 20)),
    number("puddles", "depth_mm", &PuddleParams::depth_mm, "mm", Range::closed(1, 100)),
    number("puddles", "film_mm", &PuddleParams::film_mm, "mm", Range::closed(0, 5))
        .at_most("depth_mm"),
    seed("puddles", "seed", &PuddleParams::seed),
};
static_assert(well_formed<PuddleParams>(kPuddleParams));

struct RippleParams {
  /// Impacts on standing water start ring ripples (sim/ripples.h).
  bool enabled = true;
  /// How long a ring on a puddle lasts before it has faded away.
  double lifetime_s = 0.5;
};

/// [ripples]
inline constexpr Param<RippleParams> kRippleParams[] = {
    flag("ripples", "enabled", &RippleParams::enabled),
    number("ripples", "lifetime_s", &RippleParams::lifetime_s, "s", Range::closed(0.05, 5)),
};
static_assert(well_formed<RippleParams>(kRippleParams));

struct LightningParams {
  /// Lightning on or off.
  bool enabled = false;
  /// Mean strike rate of the Poisson process.
  double strikes_per_minute = 6.0;
  /// L-system generations (trunk = 0, branches, sub-branches…).
  int generations = 5;
  /// Height of the cloud base where bolts start.
  double cloud_height_m = 300.0;
  /// Where strikes land, as seen from the camera: degrees from its horizontal view direction,
  /// positive to the right. The clip's first strike lands exactly there.
  double azimuth_deg = 0.0;
  /// Later strikes land within ± this of azimuth_deg (uniformly).
  double azimuth_spread_deg = 25.0;
  /// Horizontal distance of the clip's first strike from the camera.
  double distance_m = 400.0;
  /// Horizontal distance of later strikes from the camera: [min, max].
  double distance_min_m = 80.0;
  double distance_max_m = 400.0;
  /// Radius of the trunk.
  double trunk_radius_m = 0.6;
  /// Return strokes per flash.
  int return_strokes = 3;
  /// Length of a flash.
  double flash_duration_s = 0.35;
  /// Force a strike at this time; < 0 means none. Lets a short example show lightning
  /// deterministically.
  double first_strike_s = -1.0;
};

/// [lightning] (its `light` key is povgen's: povgen/export_params.h)
inline constexpr Param<LightningParams> kLightningParams[] = {
    flag("lightning", "enabled", &LightningParams::enabled),
    number("lightning", "strikes_per_minute", &LightningParams::strikes_per_minute, "1/min",
           Range::closed(0, 600)),
    integer("lightning", "generations", &LightningParams::generations, "", 1, 8),
    number("lightning", "cloud_height_m", &LightningParams::cloud_height_m, "m",
           Range::closed(10, 5000)),
    number("lightning", "azimuth_deg", &LightningParams::azimuth_deg, "°",
           Range::closed(-180, 180)),
    number("lightning", "azimuth_spread_deg", &LightningParams::azimuth_spread_deg, "°",
           Range::closed(0, 180)),
    // Beyond 10 km a bolt from a cloud base of at most 5 km is a few pixels tall and its
    // flash, as the environments light it, no longer reaches the street.
    number("lightning", "distance_m", &LightningParams::distance_m, "m", Range::closed(0, 10000)),
    number("lightning", "distance_min_m", &LightningParams::distance_min_m, "m",
           Range::closed(0, 10000))
        .at_most("distance_max_m"),
    number("lightning", "distance_max_m", &LightningParams::distance_max_m, "m",
           Range::closed(0, 10000)),
    number("lightning", "trunk_radius_m", &LightningParams::trunk_radius_m, "m",
           Range::open_closed(0, 10)),
    integer("lightning", "return_strokes", &LightningParams::return_strokes, "", 1, 10),
    number("lightning", "flash_duration_s", &LightningParams::flash_duration_s, "s",
           Range::closed(0.05, 2)),
    // Negative means "no forced strike"; the upper bound only keeps the number sane.
    number("lightning", "first_strike_s", &LightningParams::first_strike_s, "s",
           Range::at_most(1e6)),
};
static_assert(well_formed<LightningParams>(kLightningParams));

struct SimParams {
  Camera camera;
  RainParams rain;
  WindParams wind;
  SplashParams splashes;
  PuddleParams puddles;
  RippleParams ripples;
  LightningParams lightning;
  /// Height of the ground plane.
  double ground_y_m = 0.0;
  /// Integration substep. Frames are advanced in whole substeps, so results do not depend on
  /// the frame rate.
  double substep_s = 0.002;
  /// Simulated time before frame 1 so the volume is already full of falling rain. The default
  /// (−1, "automatic") lets World pick 0.2 s: the volume is filled at steady-state density
  /// first, so only merging needs the time (the ground's impacts from before the drops start
  /// are sampled from the flux).
  double prewarm_s = -1.0;
  /// Worker threads for a step, in [0, 1024]; 0 = all cores. Results never depend on it. Not a
  /// scene-file key.
  int threads = 0;
  /// Seed of every random stream.
  std::uint64_t seed = 1;
  /// Where the environment's lamps are (their lenses, m), for rain.lamp_reach_m. Set by cli from
  /// the environment, not a scene-file key.
  std::vector<glm::dvec3> lamps;
};

/// The top-level `seed` and [simulation]; the other sections have their own tables above.
inline constexpr Param<SimParams> kSimParams[] = {
    seed("", "seed", &SimParams::seed),
    number("simulation", "substep_s", &SimParams::substep_s, "s", Range::closed(1e-4, 0.02)),
    number("simulation", "prewarm_s", &SimParams::prewarm_s, "s", Range::closed(0, 60))
        .unset_as("automatic"),
    number("simulation", "ground_y_m", &SimParams::ground_y_m, "m", kCoordinates),
};
static_assert(well_formed<SimParams>(kSimParams));

/// Throws std::invalid_argument naming the first field out of its range (the tables above),
/// e.g. "rain.far_m must be > rain.near_m (got 0.2 <= 0.3)". World's constructor calls it.
void validate(const SimParams& params);

}  // namespace raintrace::sim
