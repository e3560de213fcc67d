// Rain around the lamps in view: one narrow World per lamp (see lamp_rain.h).
#include "sim/lamp_rain.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <utility>

#include "sim/drop_size.h"
#include "sim/drop_state.h"
#include "sim/random.h"
#include "sim/terminal_velocity.h"

namespace raintrace::sim {
namespace {

/// The scene's rain, seen from the same eye through a frustum just wide enough for the ball of
/// radius reach_m around centre and no deeper than it, with nothing on the ground.
SimParams lamp_params(const SimParams& scene, const glm::dvec3& centre, double distance_m,
                      double reach_m, std::uint64_t lamp_number) {
  SimParams p = scene;
  p.camera.look_at = centre;
  p.camera.fov_deg = 2.0 * std::asin(reach_m / distance_m) * 180.0 / std::numbers::pi;
  p.camera.aspect = 1.0;
  p.rain.near_m = std::max(scene.rain.far_m, distance_m - reach_m);
  p.rain.far_m = distance_m + reach_m;
  p.splashes.enabled = false;
  p.ripples.enabled = false;
  p.puddles.coverage = 0.0;
  p.lightning.enabled = false;
  // Merging changes a few drops in a thousand over a fall (a pass every 40 ms is most of a
  // step's cost): for rain seen 15 m away and more, not worth it.
  p.rain.merging = false;
  p.seed = mix64(scene.seed ^ mix64(lamp_number));
  return p;
}

/// Where the ball of drawn rain sits: reach_m/2 below the lens and reach_m/2 nearer the eye
/// (across the ground). A street lamp lights the air below it, and of that air the camera sees
/// lit from behind (a drop's bright forward lobe, sim/drop_optics.h) the part between it and the
/// lamp; the rain beyond the lamp scatters its light backward, ~1/100 as bright.
glm::dvec3 ball_centre(const glm::dvec3& lens, const glm::dvec3& eye, double reach_m) {
  glm::dvec3 toward_eye = eye - lens;
  toward_eye.y = 0.0;
  const double across = glm::length(toward_eye);
  const glm::dvec3 nearer = across > 0.0 ? toward_eye * (0.5 * reach_m / across) : glm::dvec3{};
  return lens + nearer - glm::dvec3{0.0, 0.5 * reach_m, 0.0};
}

struct LampWorld {
  glm::dvec3 centre;
  SimParams params;
};

/// The lamps that take part and their Worlds' params, in the order of params.lamps.
std::vector<LampWorld> lamp_worlds(const SimParams& params) {
  std::vector<LampWorld> worlds;
  const double reach = params.rain.lamp_reach_m;
  if (reach <= 0.0 || params.lamps.empty()) return worlds;
  const ViewVolume lamps_in_view(params.camera, params.rain.far_m,
                                 std::max(params.rain.far_m, params.rain.lamp_far_m) + 1e-6);
  for (const glm::dvec3& lens : params.lamps) {
    if (!lamps_in_view.contains(lens)) continue;
    const glm::dvec3 centre = ball_centre(lens, params.camera.position, reach);
    const double distance = glm::length(centre - params.camera.position);
    // Far enough that the ball leaves the eye out.
    if (distance <= 2.0 * reach) continue;
    const auto number = static_cast<std::uint64_t>(worlds.size() + 1);
    worlds.push_back({centre, lamp_params(params, centre, distance, reach, number)});
  }
  return worlds;
}

/// The camera's view from far_m out to the farthest ball: where a lamp's drops are drawn.
ViewVolume beyond_drawn_rain(const SimParams& params) {
  return ViewVolume(params.camera, params.rain.far_m,
                    std::max(params.rain.far_m, params.rain.lamp_far_m) +
                        2.0 * std::max(params.rain.lamp_reach_m, 1e-3));
}

}  // namespace

LampRain::LampRain(const SimParams& params, const std::atomic<bool>* cancel)
    : m_beyond(beyond_drawn_rain(params)), m_reach_m(params.rain.lamp_reach_m) {
  for (LampWorld& lamp : lamp_worlds(params)) {
    m_lamps.push_back({lamp.centre, std::make_unique<World>(lamp.params, cancel)});
  }
}

WorkEstimate LampRain::estimate(const SimParams& params) {
  WorkEstimate sum;
  for (const LampWorld& lamp : lamp_worlds(params)) {
    const WorkEstimate one = World::estimate(lamp.params);
    sum.drops += one.drops;
    sum.prewarm_steps = std::max(sum.prewarm_steps, one.prewarm_steps);
  }
  return sum;
}

LampRain::Sample LampRain::sample(const SimParams& params, int per_lamp) {
  Sample sample;
  const std::vector<LampWorld> worlds = lamp_worlds(params);
  if (worlds.empty() || per_lamp <= 0) return sample;
  const DropSizeModel sizes(params.rain);
  const double reach = params.rain.lamp_reach_m;
  const double ball_m3 = 4.0 / 3.0 * std::numbers::pi * reach * reach * reach;
  sample.drops_per_sample = sizes.number_density_per_m3() * ball_m3 / per_lamp;
  const ViewVolume beyond = beyond_drawn_rain(params);
  const glm::dvec3 wind{params.wind.velocity_m_per_s.x, 0.0, params.wind.velocity_m_per_s.z};
  DropState state;
  for (std::size_t k = 0; k < worlds.size(); ++k) {
    const std::uint64_t offset = (k + 1) * kIdStride;
    for (int i = 0; i < per_lamp; ++i) {
      NewDrop drop;
      drop.id = offset + static_cast<std::uint64_t>(i);
      auto u = [&](int dim) { return uniform(params.seed, Stream::fill, drop.id, dim); };
      // Uniform in the ball: radius ∝ u^(1/3), direction uniform on the sphere.
      const double r = reach * std::cbrt(u(0));
      const double cos_theta = 2.0 * u(1) - 1.0;
      const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
      const double phi = 2.0 * std::numbers::pi * u(2);
      const glm::dvec3 p = worlds[k].centre + r * glm::dvec3{sin_theta * std::cos(phi), cos_theta,
                                                             sin_theta * std::sin(phi)};
      if (!beyond.contains(p)) continue;
      const double diameter = sizes.sample_in_air(u(3));
      drop.position = glm::vec3(p);
      drop.velocity = glm::vec3(wind.x, -terminal_velocity(diameter), wind.z);
      drop.diameter = static_cast<float>(diameter);
      drop.vanishing_rate = static_cast<float>(params.rain.vanishing_rate_per_s);
      drop.colour = glm::vec3(params.rain.colour);
      state.push(drop);
    }
  }
  sample.drops = std::move(state.drops);
  return sample;
}

std::size_t LampRain::simulated_drops() const {
  std::size_t n = 0;
  for (const Lamp& lamp : m_lamps) n += lamp.world->drops().size();
  return n;
}

void LampRain::advance_to(double t_s) {
  for (Lamp& lamp : m_lamps) lamp.world->advance_to(t_s);
}

void LampRain::add_drops(Drops& drops) const {
  const double reach2 = m_reach_m * m_reach_m;
  for (std::size_t k = 0; k < m_lamps.size(); ++k) {
    const Lamp& lamp = m_lamps[k];
    // Straight from the World's drops: its snapshot would copy the whole frustum around the
    // ball first, a third of its drops (96 MB for heavy_rain's lamp, its run's peak).
    const Drops& own = lamp.world->drops();
    const std::uint64_t offset = (k + 1) * kIdStride;
    for (std::size_t i = 0; i < own.size(); ++i) {
      const glm::dvec3 p{own.position[i]};
      const glm::dvec3 d = p - lamp.centre;
      if (glm::dot(d, d) > reach2 || !m_beyond.contains(p)) continue;
      drops.append(own, i);
      drops.id.back() += offset;
    }
  }
}

}  // namespace raintrace::sim
