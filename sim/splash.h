// What a raindrop does when it hits wet ground: splash or not, and the droplets a splash throws.
//
// Threshold. On a wetted surface a drop splashes (throws secondary droplets from a crown) only
// when the splashing parameter K = We·Oh^−0.4 exceeds a critical value that grows with the
// water's depth relative to the drop, K_c = 2100 + 5880·δ^1.44 with δ = h/D (Cossali, Coghe &
// Marengo 1997, Exp. Fluids 22:463–472; fitted for 0.1 <= δ <= 1). We = ρDv²/σ, Oh = μ/√(ρσD),
// v the speed normal to the surface. Beyond δ ≈ 1 the threshold no longer depends on depth
// (Okawa et al. 2021 find it constant past h ≈ 0.7·D), so δ is capped at 1: a puddle deeper
// than the drop behaves like deep water. A terminal-speed 1 mm drop has We ≈ 220, Oh ≈ 0.0037,
// K ≈ 2060: right at the thin-film threshold, which is why most drops of moderate rain do not
// splash. Cossali's fit used liquids with Oh > 0.007; rain (Oh ≈ 0.002–0.005) extrapolates it.
// For comparison, Vander Wal et al. (2006, Exp. Fluids 40:53–59) put the thin-film boundary at
// √We = 20, which moves the critical terminal-speed diameter from ~1.0 to ~1.3 mm.
//
// Crown splash. Above the threshold the droplets follow Bai, Rusche & Gosman (2002, "Modeling
// of gasoline spray impingement", Atomization and Sprays 12:1–27), as OpenFOAM implements it
// (src/lagrangian/intermediate/submodels/Thermodynamic/SurfaceFilmModel/ThermoSurfaceFilm):
//   - count N = 5·(We/We_c − 1) = 5·(K/K_c − 1) (the drop's Oh is the same on both sides);
//   - splashed mass r·m, r uniform in [0.2, 1.1] (more than the drop: the film is entrained);
//   - diameters from an exponential distribution truncated to [0.1·d_max, d_max],
//     d_max = 0.9·r^(1/3)·D, whose mean d̄ gives the splashed mass: N·6·d̄³ = r·D³;
//   - kinetic energy E_k,in + E_σ,in − E_σ,out − E_d shared out, E_d = max(0.8·E_k,in, the
//     energy at the threshold), each droplet's speed ∝ ln(D/d) (small droplets are faster);
//   - ejected 5°–50° above the surface at a random azimuth, plus 0.6 of the drop's speed along
//     the surface (Bai et al. give 0.6–0.8 for the tangential "friction" coefficient).
// The droplets then fly ballistically with the same quadratic drag as raindrops (a 0.2 mm
// droplet thrown at 4 m/s stops within ~10 cm), land and are gone.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>

#include "sim/frame.h"
#include "sim/params.h"

namespace raintrace::sim {

/// Water at 20 °C: density kg/m³, surface tension N/m, dynamic viscosity Pa·s.
inline constexpr double kWaterDensity = 998.2;
inline constexpr double kWaterSurfaceTension = 0.0728;
inline constexpr double kWaterViscosity = 1.002e-3;

/// Cossali et al.'s constants: K_c = kSplashK0 + kSplashKFilm·δ^kSplashFilmExponent.
inline constexpr double kSplashK0 = 2100.0;
inline constexpr double kSplashKFilm = 5880.0;
inline constexpr double kSplashFilmExponent = 1.44;

/// We = ρ·D·v²/σ for a drop of diameter D (m) hitting at normal speed v (m/s).
double weber_number(double diameter_m, double normal_speed_m_per_s);
/// Oh = μ / √(ρ·σ·D).
double ohnesorge_number(double diameter_m);
/// K = We·Oh^−0.4.
double splashing_parameter(double diameter_m, double normal_speed_m_per_s);
/// K_c = 2100 + 5880·min(h/D, 1)^1.44 for water depth h (m) and drop diameter D (m).
double critical_splashing_parameter(double water_depth_m, double diameter_m);
/// True if the impact splashes: K > K_c.
bool splashes(double diameter_m, double normal_speed_m_per_s, double water_depth_m);
/// The diameter (m) above which drops falling at terminal speed splash on water of depth h
/// (bisection to 1e-4 of a mm on [0.1, 8] mm; K/K_c grows with D over that range).
double critical_diameter_at_terminal_speed(double water_depth_m);

/// One impact on the ground, with what decides its outcome.
struct ImpactInput {
  std::uint64_t key = 0;       ///< identity of the impact: keys its random numbers
  glm::vec3 position{0.0f};    ///< m, on the ground
  glm::vec3 velocity{0.0f};    ///< m/s at impact (y < 0)
  float diameter_m = 0.0f;     ///< drop diameter
  float water_depth_m = 0.0f;  ///< film or puddle depth where it lands
};

/// The crown splash of one impact (see above), before any droplet is drawn.
struct CrownSplash {
  double expected_droplets = 0.0;  ///< N = 5·(K/K_c − 1); 0 below the threshold
  int droplets = 0;                ///< drawn: floor(N + u), capped by SplashParams::droplets
  double mass_ratio = 0.0;         ///< splashed mass / drop mass
  double mean_diameter_m = 0.0;    ///< d̄ of the exponential distribution
  double max_diameter_m = 0.0;     ///< d_max = 0.9·r^(1/3)·D
  double kinetic_energy_j = 0.0;   ///< energy shared by all N droplets (0: too little to splash)
  double speed_scale = 0.0;        ///< U in u = U·ln(D/d), m/s: N droplets carry the energy
};

/// The crown splash of an impact; random numbers keyed by (seed, impact key).
CrownSplash crown_splash(const SplashParams& params, const ImpactInput& impact, std::uint64_t seed);

/// A secondary droplet at the moment it leaves the crown.
struct Droplet {
  glm::vec3 velocity{0.0f};  ///< m/s
  float diameter_m = 0.0f;
};

/// Droplet k (< crown.droplets) of the impact: its diameter and launch velocity. Pure.
Droplet crown_droplet(const CrownSplash& crown, const ImpactInput& impact, int k,
                      std::uint64_t seed);

/// A droplet in flight: its state after `steps` whole flight steps (2 ms) from the impact.
/// Integrating in whole steps from the impact, whatever the times it is looked at, makes its
/// path the same whether frames are taken every step, every frame or only at the end.
struct FlyingDroplet {
  std::uint64_t id = 0;  ///< hash of (impact key, droplet): stable over the flight
  double impact_time_s = 0.0;
  glm::vec3 position{0.0f};  ///< m
  glm::vec3 velocity{0.0f};  ///< m/s
  glm::vec3 wind{0.0f};      ///< air it is dragged toward: the wind its drop fell with
  float diameter_m = 0.0f;
  float drag = 0.0f;      ///< drag_coefficient(diameter), 1/m
  float weight = 1.0f;    ///< level-of-detail weight: the droplets it stands for
  float ground_y = 0.0f;  ///< height of the ground it was thrown from (and lands on)
  int steps = 0;
  bool landed = false;  ///< fell back to the ground: gone
};

/// The least share of its pixels' light a droplet must block to be drawn (launch_droplets): as
/// faint as the default's rain streaks are drawn (povgen's min_streak_coverage, 0.01). Fainter
/// droplets are left out, their light with them: together they add under 0.05 % of a frame's
/// light, and drawn as their rain's are (kept by chance, each carrying the others' light) they
/// cost 3 % of the default's frame at 1280×720 final and 10 % of a 320×240 preview
/// (BENCHMARKS.md, "Far splash droplets"). Until 2026-12-06 they were kept by chance carrying a
/// whole pixel's light: each far droplet kept stood for about a thousand and was drawn as an
/// opaque streak of water, a bright white dash on the road.
inline constexpr double kDropletCoverageFloor = 0.01;

/// Launches the droplets of an impact's crown (k < crown.droplets) from the ground with their
/// launch velocity, appended to `out`. Level of detail: with pixel_m > 0 (the width of a pixel at
/// the impact), a droplet whose weight × share of its pixels' light is below
/// kDropletCoverageFloor — its width over a pixel's, times d / (its streak's length in
/// `exposure_s`, at least a pixel): a fast droplet covers each point of its streak for a moment
/// only (Garg & Nayar) — is left out. A crown costs the droplets that show instead of dozens
/// that would not. (Taken at the launch speed: a droplet slowed by drag later blocks a little
/// more than that, so a few of those left out would show near the end of their flight.)
void launch_droplets(const CrownSplash& crown, const ImpactInput& impact, double impact_time_s,
                     float weight, double pixel_m, double exposure_s, std::uint64_t seed,
                     std::vector<FlyingDroplet>& out);

/// Advances the droplet in whole steps up to floor(age_s / step) under gravity and quadratic
/// drag (the raindrops' drag law) toward its wind; marks it landed when it falls below its
/// ground.
void fly(FlyingDroplet& droplet, double age_s);

/// Appends the droplet as it is age_s after its impact (its whole-step state plus the partial
/// step, not stored) to `out`, unless it has landed or age_s >= params.lifetime_s. Its opacity
/// is its weight, fading over the last third of lifetime_s.
void add_droplet(const SplashParams& params, const FlyingDroplet& droplet, double age_s,
                 Drops& out);

/// Everything at once, for one impact `age_s` after it (launch, fly, add). Pure.
void add_splash_droplets(const SplashParams& params, const ImpactInput& impact, double age_s,
                         float weight, double pixel_m, double exposure_s, std::uint64_t seed,
                         Drops& out);

}  // namespace raintrace::sim
