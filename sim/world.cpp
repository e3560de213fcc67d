// World orchestration: fill, prewarm, substeps (integrate → ground hits and removals → spawn →
// merge), snapshot. See world.h for the contract.
#include "sim/world.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>

#include "sim/breakup.h"
#include "sim/merging.h"
#include "sim/random.h"
#include "sim/ripples.h"
#include "sim/splash.h"
#include "sim/terminal_velocity.h"

namespace raintrace::sim {
namespace {

// Below this many drops a substep is too short to be worth a second thread.
constexpr std::size_t kParallelMin = 32768;
// Merging runs every ~40 ms of simulated time (about a frame); the swept test covers the gap
// (merging.h): over 40 ms drops move on near-straight lines.
constexpr double kMergeInterval_s = 0.04;
// A drop fainter than this can no longer be seen (1/255 of full opacity).
constexpr float kMinOpacity = 1.0f / 255.0f;

/// params, once validated: World's first member is initialised from it, so nothing uses a
/// value before it has been checked.
const SimParams& validated(const SimParams& params) {
  validate(params);
  return params;
}

// How far beyond the steady wind drops may drift sideways, as a speed, m/s. Gusts and
// turbulence are zero-mean oscillations, so their net drift over a fall is a fraction of their
// peak; a quarter of the gust peak and half the turbulence RMS cover it (more would multiply
// the drops simulated out of view for nothing).
double wind_spread(const WindParams& w) {
  return (w.gusts ? 0.25 * kGustPeak * w.gust_strength : 0.0) + 0.5 * w.turbulence_m_per_s;
}

/// How long after an impact something of it still shows: splash droplets fly up to
/// splashes.lifetime_s, rings on puddles last ripples.lifetime_s (film ripples less).
double impact_memory(const SimParams& p) {
  double memory = 0.0;
  if (p.splashes.enabled) memory = std::max(memory, p.splashes.lifetime_s);
  if (p.ripples.enabled) memory = std::max(memory, p.ripples.lifetime_s);
  return memory;
}

double default_prewarm(const SimParams&) {
  // The fill already puts drops at their steady-state density and speed; what still needs
  // time is a few merging passes. The ground's impacts from before the drops started are
  // sampled from the flux (ImpactSampler's volume_start_s), so frame 1 has its ripples anyway.
  return 0.2;
}

// Ripples are drawn ring by ring while a pixel spans at most a ring wavelength: beyond, the
// pixel filter leaves under 0.1 % of a ring (sim/ripples.h) and the renderer draws the
// roughness the rings add instead (ripple_slope_rms()).

ImpactInput impact_input(const GroundImpact& impact) {
  ImpactInput in;
  in.key = impact.key;
  in.position = impact.position;
  in.velocity = impact.velocity;
  in.diameter_m = impact.diameter_m;
  in.water_depth_m = impact.water_depth_m;
  return in;
}

}  // namespace

World::World(const SimParams& params, const std::atomic<bool>* cancel)
    : m_params(validated(params)),
      m_cancel(cancel),
      m_view(params.camera, params.rain.near_m, params.rain.far_m),
      m_wind(params.wind, params.seed),
      m_sizes(params.rain),
      m_region(m_view, params.ground_y_m, params.rain.ceiling_margin_m,
               glm::dvec3{params.wind.velocity_m_per_s.x, 0.0, params.wind.velocity_m_per_s.z},
               wind_spread(params.wind), terminal_velocity(params.rain.diameter_min_mm * 1e-3)),
      m_puddles(params.puddles, params.puddles.seed),
      m_detail(params.camera),
      m_sampler(params.camera, params.ground_y_m, m_sizes, m_region, m_detail, params.seed),
      m_schedule(params.lightning, params.seed) {
  const double expected = m_sizes.number_density_per_m3() * m_region.volume_m3();
  if (expected > kMaxDrops) {
    throw std::invalid_argument(
        "rain: the simulated volume would hold " +
        std::to_string(static_cast<long long>(expected)) +
        " drops (more than 50 million); reduce rain.far_m or rain.rate_mm_per_h");
  }
  const double prewarm = m_params.prewarm_s < 0.0 ? default_prewarm(m_params) : m_params.prewarm_s;
  m_prewarm_steps = std::llround(prewarm / m_params.substep_s);
  m_merge_every = std::max(1, static_cast<int>(std::lround(kMergeInterval_s / m_params.substep_s)));
  m_events.resize(static_cast<std::size_t>(thread_count()));
  // Sampled impacts do not depend on the drops: start early enough that frame 1 shows the
  // splashes and ripples of the moments before it, whatever the prewarm; the footprint's own
  // are sampled too until the volume's drops start landing.
  m_volume_start_s = time_s();
  m_next_slot = static_cast<std::int64_t>(
      std::floor((time_s() - impact_memory(m_params)) / ImpactSampler::kSlot_s));
  fill();
  while (m_step < m_prewarm_steps) {
    check_cancel();
    step();
  }
}

WorkEstimate World::estimate(const SimParams& params) {
  validate(params);
  const ViewVolume view(params.camera, params.rain.near_m, params.rain.far_m);
  const DropSizeModel sizes(params.rain);
  const SpawnRegion region(
      view, params.ground_y_m, params.rain.ceiling_margin_m,
      glm::dvec3{params.wind.velocity_m_per_s.x, 0.0, params.wind.velocity_m_per_s.z},
      wind_spread(params.wind), terminal_velocity(params.rain.diameter_min_mm * 1e-3));
  WorkEstimate e;
  // The World fills the box but keeps only the drops that can reach the footprint (fill): in
  // wind about half of them. Averaged over the sizes' quantiles, each falling at its own speed.
  constexpr int kSizeQuantiles = 64;
  double reachable_m3 = 0.0;
  for (int k = 0; k < kSizeQuantiles; ++k) {
    const double diameter = sizes.sample_in_air((k + 0.5) / kSizeQuantiles);
    reachable_m3 += region.reachable_volume_m3(terminal_velocity(diameter)) / kSizeQuantiles;
  }
  e.drops = sizes.number_density_per_m3() * reachable_m3;
  e.drops_in_view = sizes.number_density_per_m3() * view.volume_m3();
  const double prewarm = params.prewarm_s < 0.0 ? default_prewarm(params) : params.prewarm_s;
  e.prewarm_steps = std::round(prewarm / params.substep_s);
  return e;
}

void World::check_cancel() const {
  if (m_cancel != nullptr && m_cancel->load(std::memory_order_relaxed)) throw Cancelled{};
}

std::optional<NewDrop> World::new_drop(std::uint64_t id, double across, double along, double y,
                                       double diameter, double terminal_speed,
                                       const glm::dvec3& wind) const {
  const double a = m_region.a0() + across * (m_region.a1() - m_region.a0());
  const double b = m_region.b0() + along * (m_region.b1() - m_region.b0());
  if (!m_region.reaches_footprint(a, b, y, terminal_speed)) return std::nullopt;
  NewDrop drop;
  drop.id = id;
  drop.position = glm::vec3(m_region.point(a, b, y));
  drop.velocity = glm::vec3(wind.x, -terminal_speed, wind.z);
  drop.diameter = static_cast<float>(diameter);
  drop.vanishing_rate = static_cast<float>(m_params.rain.vanishing_rate_per_s);
  drop.colour = glm::vec3(m_params.rain.colour);
  return drop;
}

int World::thread_count() const {
  if (m_params.threads > 0) return m_params.threads;
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

double World::time_s() const {
  return static_cast<double>(m_step - m_prewarm_steps) * m_params.substep_s;
}

void World::fill() {
  const double count = std::round(m_sizes.number_density_per_m3() * m_region.volume_m3());
  const auto n = static_cast<std::size_t>(count);
  m_state.reserve(n + n / 4);
  const glm::dvec3 wind = m_wind.uniform_at(time_s());
  const auto rate = static_cast<float>(m_params.rain.vanishing_rate_per_s);
  for (std::size_t k = 0; k < n; ++k) {
    if (k % 65536 == 0) check_cancel();  // tens of millions of drops take seconds
    const std::uint64_t id = m_next_id++;
    auto u = [&](int dim) { return uniform(m_params.seed, Stream::fill, id, dim); };
    const double d = m_sizes.sample_in_air(u(0));
    const double vt = terminal_velocity(d);
    const double y = m_region.ground() + u(3) * (m_region.ceiling() - m_region.ground());
    // Drawn (so ids and the rest of the fill do not depend on it), but maybe not simulated.
    std::optional<NewDrop> drop = new_drop(id, u(1), u(2), y, d, vt, wind);
    if (!drop) continue;
    // As if it had fallen from the ceiling at terminal velocity.
    drop->age = static_cast<float>((m_region.ceiling() - y) / vt);
    drop->opacity = std::exp(-rate * drop->age);
    m_state.push(*drop);
  }
}

void World::spawn(double t_s) {
  const double dt = m_params.substep_s;
  const double expected = m_sizes.number_flux_per_m2_s() * m_region.spawn_area_m2() * dt;
  // floor(λ + u) has mean λ exactly and no state carried between substeps.
  const auto n = static_cast<std::size_t>(std::floor(
      expected + uniform(m_params.seed, Stream::spawn_count, static_cast<std::uint64_t>(m_step))));
  const glm::dvec3 wind = m_wind.uniform_at(t_s);
  const double breakup_m = m_params.rain.breakup_diameter_mm * 1e-3;
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint64_t id = m_next_id++;
    auto u = [&](int dim) { return uniform(m_params.seed, Stream::drop, id, dim); };
    const double d = m_sizes.sample_in_flux(u(0));
    const double vt = terminal_velocity(d);
    // Born somewhere within this substep's fall below the ceiling, so that no layers form.
    const double y = m_region.ceiling() - u(3) * vt * dt;
    std::optional<NewDrop> drop = new_drop(id, u(1), u(2), y, d, vt, wind);
    if (!drop) continue;
    m_state.push(*drop);
    if (d > breakup_m) {
      m_breakups += break_up(m_state, m_state.size() - 1, breakup_m, m_next_id, m_params.seed) > 0;
    }
  }
}

void World::handle_events(double t_end_s) {
  const bool counting = t_end_s > 0.0;
  const float ground = static_cast<float>(m_region.ground());
  m_removals.clear();
  Drops& d = m_state.drops;
  for (const StepEvents& ev : m_events) {
    for (const std::uint32_t i : ev.ground) {
      const glm::vec3 p = d.position[i], v = d.velocity[i];
      // Back along this substep's motion to where the drop crossed the ground.
      const float tau = v.y < 0.0f ? (p.y - ground) / v.y : 0.0f;
      glm::vec3 hit = p - v * tau;
      hit.y = ground;
      const double diameter = d.diameter[i];
      const bool measured = m_region.in_measure_area(glm::dvec3(hit));
      if (counting) {
        ++m_ground_hits;
        if (measured) {
          m_ground_water_m3 += diameter * diameter * diameter * (std::numbers::pi / 6.0);
        }
      }
      // The footprint is the volume's ground (ground_impacts.h); outside it the sampler's.
      const double keep = m_detail.keep(glm::dvec3(hit));
      if (measured && uniform(m_params.seed, Stream::ground_detail, d.id[i]) < keep) {
        GroundImpact impact;
        impact.key = d.id[i];
        impact.time_s = t_end_s - tau;
        impact.position = hit;
        impact.velocity = v;
        impact.diameter_m = d.diameter[i];
        impact.weight = static_cast<float>(1.0 / keep);
        count(record_impact(impact));
      }
      m_removals.push_back(i);
    }
    m_removals.insert(m_removals.end(), ev.gone.begin(), ev.gone.end());
  }
  // Descending order: every index above the current one is already gone, so the drop moved
  // into place by swap_remove is never one still to be removed.
  std::sort(m_removals.begin(), m_removals.end(), std::greater<>());
  for (const std::uint32_t i : m_removals) m_state.swap_remove(i);
}

double World::impact_memory_s() const { return impact_memory(m_params); }

World::Tally World::record_impact(const GroundImpact& in) {
  GroundImpact& impact = m_impacts.emplace_back(in);
  const PuddleField::Water water = m_puddles.water_at(in.position.x, in.position.z);
  impact.water_depth_m = static_cast<float>(water.depth_m);
  impact.on_puddle = water.puddle;
  if (m_params.splashes.enabled) {
    impact.crown = crown_splash(m_params.splashes, impact_input(impact), m_params.seed);
  }
  return {impact.time_s, impact.weight, impact.crown.expected_droplets > 0.0,
          m_params.ripples.enabled && impact.on_puddle};
}

void World::count(const Tally& tally) {
  if (tally.time_s < 0.0) return;  // prewarm: not counted
  ++m_ground_impacts_simulated;
  m_ground_impacts += tally.weight;
  if (tally.splash) m_splash_events += tally.weight;
  if (tally.ripple) m_ripple_events += tally.weight;
}

void World::count_until(double t_end_s) {
  while (m_uncounted_next < m_uncounted.size() && m_uncounted[m_uncounted_next].time_s < t_end_s) {
    count(m_uncounted[m_uncounted_next++]);
  }
  if (m_uncounted_next > 4096 && 2 * m_uncounted_next > m_uncounted.size()) {
    m_uncounted.erase(m_uncounted.begin(),
                      m_uncounted.begin() + static_cast<std::ptrdiff_t>(m_uncounted_next));
    m_uncounted_next = 0;
  }
}

void World::sample_ground(double t_end_s) {
  const auto slot_start = [](std::int64_t slot) {
    return static_cast<double>(slot) * ImpactSampler::kSlot_s;
  };
  if (slot_start(m_next_slot) >= t_end_s) return;
  // Forget impacts that no longer show, keeping the order of the rest.
  const double oldest = t_end_s - impact_memory_s() - m_params.substep_s;
  std::erase_if(m_impacts, [oldest](const GroundImpact& i) { return i.time_s < oldest; });
  std::vector<GroundImpact> sampled;
  while (slot_start(m_next_slot) < t_end_s) {
    sampled.clear();
    m_sampler.sample(m_next_slot, m_wind.uniform_at(slot_start(m_next_slot)), sampled,
                     m_volume_start_s);
    // A slot is sampled at its start but its impacts happen during it: they are counted as
    // their times pass (count_until), in time order (slots follow each other).
    const std::size_t first = m_uncounted.size();
    for (const GroundImpact& impact : sampled) m_uncounted.push_back(record_impact(impact));
    std::stable_sort(m_uncounted.begin() + static_cast<std::ptrdiff_t>(first), m_uncounted.end(),
                     [](const Tally& a, const Tally& b) { return a.time_s < b.time_s; });
    ++m_next_slot;
  }
}

void World::step() {
  const double t = time_s();
  const double dt = m_params.substep_s;
  StepConstants c;
  c.dt = static_cast<float>(dt);
  c.time_s = t;
  c.wind = glm::vec3(m_wind.uniform_at(t));
  c.turbulence = m_wind.has_turbulence() ? &m_wind : nullptr;
  c.origin = glm::vec3(m_region.origin());
  c.across = glm::vec3(m_region.across_axis());
  c.along = glm::vec3(m_region.along_axis());
  c.a0 = static_cast<float>(m_region.a0());
  c.a1 = static_cast<float>(m_region.a1());
  c.b0 = static_cast<float>(m_region.b0());
  c.b1 = static_cast<float>(m_region.b1());
  c.ground = static_cast<float>(m_region.ground());
  c.ceiling = static_cast<float>(m_region.ceiling());
  c.fa0 = static_cast<float>(m_region.fa0());
  c.fa1 = static_cast<float>(m_region.fa1());
  c.fb0 = static_cast<float>(m_region.fb0());
  c.fb1 = static_cast<float>(m_region.fb1());
  c.ea0 = static_cast<float>(m_region.ea0());
  c.ea1 = static_cast<float>(m_region.ea1());
  c.eb0 = static_cast<float>(m_region.eb0());
  c.eb1 = static_cast<float>(m_region.eb1());
  c.min_opacity = kMinOpacity;
  c.fading = m_params.rain.vanishing_rate_per_s > 0.0;

  const std::size_t n = m_state.size();
  for (StepEvents& ev : m_events) ev.clear();
  const std::size_t chunks =
      n >= kParallelMin ? std::min<std::size_t>(m_events.size(), n / (kParallelMin / 2)) : 1;
  if (chunks <= 1) {
    integrate_range(m_state, 0, n, c, m_events[0]);
  } else {
    // Chunk k covers [k·n/chunks, (k+1)·n/chunks); events are concatenated in chunk order,
    // i.e. ascending drop index, whatever the number of chunks.
    std::vector<std::jthread> workers;
    workers.reserve(chunks - 1);
    for (std::size_t k = 1; k < chunks; ++k) {
      workers.emplace_back([&, k] {
        integrate_range(m_state, k * n / chunks, (k + 1) * n / chunks, c, m_events[k]);
      });
    }
    integrate_range(m_state, 0, n / chunks, c, m_events[0]);
  }
  handle_events(t + dt);
  sample_ground(t + dt);
  count_until(t + dt);
  spawn(t);
  ++m_step;
  if (m_params.rain.merging && m_step % m_merge_every == 0) {
    const MergeResult r = merge_touching(m_state, static_cast<float>(m_merge_every * dt),
                                         m_params.rain.breakup_diameter_mm * 1e-3, m_next_id,
                                         m_params.seed, &m_wind, time_s());
    m_merges += r.merges;
    m_breakups += r.breakups;
  }
  if (m_params.lightning.enabled) m_strikes = m_schedule.strikes_until(time_s());
}

void World::advance_to(double t_s) {
  const double steps = (t_s - time_s()) / m_params.substep_s + 1e-6;
  if (!(steps >= 1.0)) return;
  const auto target = m_step + static_cast<std::int64_t>(std::floor(steps));
  while (m_step < target) {
    check_cancel();
    step();
  }
}

void World::add_ground_effects(Frame& f) const {
  const double memory = impact_memory_s();
  const double lifetime = m_params.splashes.lifetime_s;
  // Impacts since the last snapshot launch their droplets (every impact up to f.time_s has been
  // recorded by now: the World only moves forward, and snapshots with it).
  for (const GroundImpact& impact : m_impacts) {
    const double age = f.time_s - impact.time_s;
    if (impact.crown.droplets == 0 || impact.time_s <= m_flying_until_s || age < 0.0 ||
        age >= lifetime) {
      continue;
    }
    launch_droplets(impact.crown, impact_input(impact), impact.time_s, impact.weight,
                    m_detail.pixel_m(glm::dvec3(impact.position)), m_params.camera.exposure_s,
                    m_params.seed, m_flying);
  }
  m_flying_until_s = std::max(m_flying_until_s, f.time_s);
  // In flight order: the impacts are recorded out of time order (sampled slots run ahead of the
  // volume's drops), so launching them a frame at a time or all at once orders them differently,
  // and a frame's text would depend on which frames were taken before it.
  std::ranges::sort(m_flying, [](const FlyingDroplet& a, const FlyingDroplet& b) {
    return std::tie(a.impact_time_s, a.id) < std::tie(b.impact_time_s, b.id);
  });
  std::erase_if(m_flying, [&](FlyingDroplet& d) {
    const double age = f.time_s - d.impact_time_s;
    fly(d, age);
    return d.landed || age >= lifetime;
  });
  for (const FlyingDroplet& d : m_flying) {
    add_droplet(m_params.splashes, d, f.time_s - d.impact_time_s, f.splashes);
  }
  if (!m_params.ripples.enabled) return;
  for (const GroundImpact& impact : m_impacts) {
    const double age = f.time_s - impact.time_s;
    if (age < 0.0 || age >= memory ||
        m_detail.pixel_m(glm::dvec3(impact.position)) > ripple_wavelength()) {
      continue;
    }
    const Ripple ripple = make_ripple(impact.position, impact.diameter_m, age, impact.water_depth_m,
                                      impact.on_puddle, m_params.ripples.lifetime_s);
    if (ripple.lifetime_s > 0.0f) f.ripples.push_back(ripple);
  }
}

Frame World::snapshot(int frame_index) const {
  Frame f;
  f.index = frame_index;
  f.time_s = time_s();
  const Drops& d = m_state.drops;
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (!m_view.contains(glm::dvec3(d.position[i]))) continue;
    f.drops.append(d, i);
  }
  add_ground_effects(f);
  // A frame records the light of its exposure: the shutter is open from time_s for
  // camera.exposure_s (the window the streaks span), and a flash counts by its average over it.
  float flash = 0.0f;
  const double exposure = m_params.camera.exposure_s;
  for (const auto& strike : m_strikes) {
    const double since = f.time_s - strike.time_s;
    if (since + exposure < 0.0 || since > m_params.lightning.flash_duration_s) continue;
    const FlashExposure light =
        flash_exposure(m_params.lightning, since, exposure, m_params.seed, strike.id);
    Bolt bolt;
    bolt.id = strike.id;
    bolt.brightness = static_cast<float>(light.all_strokes);
    bolt.branch_brightness = static_cast<float>(light.first_stroke);
    const BoltSkeleton skeleton =
        with_kinks(build_bolt(m_params.lightning, m_params.camera, m_params.ground_y_m,
                              m_params.seed, strike.id),
                   m_params.ground_y_m, m_params.seed, strike.id);
    for (const BoltBranch& branch : skeleton.branches) {
      bolt.segments.insert(bolt.segments.end(), branch.segments.begin(), branch.segments.end());
    }
    flash += bolt.brightness;
    f.bolts.push_back(std::move(bolt));
  }
  f.flash = std::min(flash, 1.0f);
  f.lightning_strikes = m_strikes.size();
  f.wind_m_per_s = m_wind.at(glm::vec3(m_params.camera.look_at), f.time_s);
  f.ground_water_m3 = m_ground_water_m3;
  f.ground_area_m2 = m_region.measure_area_m2();
  f.ground_hits = m_ground_hits;
  f.ground_impacts = m_ground_impacts;
  f.splash_events = m_splash_events;
  f.ripple_events = m_ripple_events;
  f.ground_impacts_simulated = m_ground_impacts_simulated;
  f.impact_area_m2 = m_region.measure_area_m2() + m_sampler.area_m2();
  f.view_volume_m3 = m_view.volume_m3();
  return f;
}

}  // namespace raintrace::sim
