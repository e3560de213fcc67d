// Lightning skeletons, flash envelopes and strike schedule (see lightning.h).
#include "sim/lightning.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "sim/perpendicular_basis.h"
#include "sim/random.h"

namespace raintrace::sim {
namespace {

constexpr int kMaxTrunkSteps = 160;

// Draws from the bolt's own stream: counter increments so each draw is a fresh key.
class BoltRandom {
 public:
  BoltRandom(std::uint64_t seed, std::uint64_t strike) : m_seed(seed), m_strike(strike) {}
  double next() { return uniform(m_seed, Stream::bolt, m_strike, m_counter++); }
  double symmetric() { return 2.0 * next() - 1.0; }
  glm::dvec3 in_ball() { return glm::dvec3{symmetric(), symmetric(), symmetric()}; }

 private:
  std::uint64_t m_seed, m_strike, m_counter = 0;
};

// Walks from `start` along `dir` in `steps` steps whose length shrinks by `shrink`, jittering
// the direction, stopping at the ground. Returns the segments.
std::vector<BoltSegment> walk(glm::dvec3 start, glm::dvec3 dir, double first_step, double shrink,
                              int steps, double jitter, float radius, int generation,
                              double ground_y, BoltRandom& rng) {
  std::vector<BoltSegment> out;
  double step = first_step;
  for (int k = 0; k < steps; ++k) {
    const glm::dvec3 d = glm::normalize(dir + jitter * rng.in_ball());
    glm::dvec3 end = start + step * d;
    bool ground = false;
    if (end.y <= ground_y) {
      const double f = (start.y - ground_y) / (start.y - end.y);
      end = start + f * (end - start);
      end.y = ground_y;
      ground = true;
    }
    out.push_back({glm::vec3(start), glm::vec3(end), radius, generation});
    if (ground) break;
    start = end;
    step *= shrink;
  }
  return out;
}

/// Splits the segment a→b into pieces at most kKinkSpacingM long (with_kinks in lightning.h),
/// appending them to `out` in order from a to b.
void split_into_kinks(glm::dvec3 a, glm::dvec3 b, const BoltSegment& like, double ground_y,
                      std::uint64_t seed, std::uint64_t strike, std::uint64_t& counter,
                      std::vector<BoltSegment>& out) {
  const double length = glm::length(b - a);
  if (length <= kKinkSpacingM) {
    out.push_back({glm::vec3(a), glm::vec3(b), like.radius, like.generation});
    return;
  }
  const glm::dvec3 along = (b - a) / length;
  const PerpendicularBasis across = perpendicular_basis(along);
  // Box-Muller: two independent standard normals from two uniforms.
  const double r =
      std::sqrt(-2.0 * std::log(1.0 - uniform(seed, Stream::bolt_kinks, strike, counter++)));
  const double phi = 2.0 * std::numbers::pi * uniform(seed, Stream::bolt_kinks, strike, counter++);
  glm::dvec3 mid = 0.5 * (a + b) +
                   kKinkSigma * length * r * (std::cos(phi) * across.u + std::sin(phi) * across.v);
  mid.y = std::max(mid.y, ground_y);
  split_into_kinks(a, mid, like, ground_y, seed, strike, counter, out);
  split_into_kinks(mid, b, like, ground_y, seed, strike, counter, out);
}

}  // namespace

BoltSkeleton with_kinks(const BoltSkeleton& bolt, double ground_y_m, std::uint64_t seed,
                        std::uint64_t strike) {
  BoltSkeleton out;
  std::uint64_t counter = 0;
  for (const BoltBranch& branch : bolt.branches) {
    BoltBranch kinked;
    kinked.generation = branch.generation;
    kinked.parent = branch.parent;
    for (const BoltSegment& s : branch.segments) {
      split_into_kinks(glm::dvec3(s.start), glm::dvec3(s.end), s, ground_y_m, seed, strike, counter,
                       kinked.segments);
    }
    out.branches.push_back(std::move(kinked));
  }
  return out;
}

std::vector<int> fibonacci_branch_counts(int generations) {
  std::vector<int> counts;
  int a = 1, b = 1;  // F(1), F(2)
  for (int g = 0; g < generations; ++g) {
    counts.push_back(a);
    const int c = a + b;
    a = b;
    b = c;
  }
  return counts;
}

bool is_first_strike(const LightningParams& params, std::uint64_t strike) {
  return params.first_strike_s >= 0.0 ? strike == 0 : strike == 1;
}

BoltSkeleton build_bolt(const LightningParams& params, const Camera& camera, double ground_y_m,
                        std::uint64_t seed, std::uint64_t strike) {
  BoltRandom rng(seed, strike);
  // Azimuth is measured from the camera's horizontal view direction, positive to the right
  // (+x when looking along +z, as the camera's image has it).
  glm::dvec3 fwd = camera.look_at - camera.position;
  fwd.y = 0.0;
  fwd = glm::length(fwd) > 0.0 ? glm::normalize(fwd) : glm::dvec3{0.0, 0.0, 1.0};
  // Both draws happen for every strike, so the rest of the bolt's random numbers do not depend
  // on whether it is the first.
  const double spread = rng.symmetric() * params.azimuth_spread_deg;
  const double along = rng.next();
  const bool opening = is_first_strike(params, strike);
  const double azimuth = (params.azimuth_deg + (opening ? 0.0 : spread)) * std::numbers::pi / 180.0;
  const glm::dvec3 dir{fwd.x * std::cos(azimuth) + fwd.z * std::sin(azimuth), 0.0,
                       fwd.z * std::cos(azimuth) - fwd.x * std::sin(azimuth)};
  const double distance =
      opening ? params.distance_m
              : params.distance_min_m + along * (params.distance_max_m - params.distance_min_m);
  const double height = params.cloud_height_m;
  glm::dvec3 ground_point = camera.position + distance * dir;
  ground_point.y = ground_y_m;
  glm::dvec3 top = ground_point + glm::dvec3{0.25 * height * rng.symmetric(), height,
                                             0.25 * height * rng.symmetric()};

  BoltSkeleton bolt;
  // Trunk: steps shrink geometrically (ratio 0.97) toward the ground, each re-aimed at the
  // ground point with jitter, so the channel zig-zags but always lands.
  BoltBranch trunk;
  {
    glm::dvec3 pos = top;
    double step = height / 12.0;
    const auto radius = static_cast<float>(params.trunk_radius_m);
    for (int k = 0; k < kMaxTrunkSteps && pos.y > ground_y_m; ++k) {
      const glm::dvec3 aim = glm::normalize(ground_point - pos);
      auto seg =
          walk(pos, aim, std::max(step, height / 80.0), 1.0, 1, 0.6, radius, 0, ground_y_m, rng);
      trunk.segments.push_back(seg.front());
      pos = glm::dvec3(seg.front().end);
      step *= 0.93;
    }
    if (pos.y > ground_y_m) {  // safety: finish straight down to the ground point
      trunk.segments.push_back({glm::vec3(pos), glm::vec3(ground_point), radius, 0});
    }
  }
  bolt.branches.push_back(std::move(trunk));

  const std::vector<int> counts = fibonacci_branch_counts(params.generations);
  int parent_begin = 0, parent_count = 1;
  for (int g = 1; g < params.generations; ++g) {
    const int child_begin = static_cast<int>(bolt.branches.size());
    for (int c = 0; c < counts[g]; ++c) {
      // Child c goes to parent c mod parent_count: every parent gets one, the first
      // counts[g−2] (the mature ones) a second — the rabbit rule.
      const int parent_index = parent_begin + c % parent_count;
      const BoltBranch& parent = bolt.branches[parent_index];
      const auto& segs = parent.segments;
      double length = 0.0;
      for (const auto& s : segs) length += glm::length(glm::dvec3(s.end) - glm::dvec3(s.start));
      // A branch leaves its parent somewhere along the upper 70 % of the parent's length (by
      // length, not by step: the trunk's steps shrink toward the ground, and picking a step
      // would put most branches near the ground, where real ones are fewest).
      const double leave = rng.next() * 0.7 * length;
      std::size_t at = 0;
      for (double run = 0.0; at + 1 < segs.size(); ++at) {
        run += glm::length(glm::dvec3(segs[at].end) - glm::dvec3(segs[at].start));
        if (run >= leave) break;
      }
      const glm::dvec3 start(segs[at].start);
      const glm::dvec3 pdir =
          glm::normalize(glm::dvec3(segs.back().end) - glm::dvec3(segs.front().start));
      const glm::dvec3 side = glm::normalize(glm::dvec3{rng.symmetric(), 0.0, rng.symmetric()} +
                                             glm::dvec3{1e-3, 0.0, 0.0});
      const glm::dvec3 bdir = glm::normalize(pdir + (0.6 + 0.6 * rng.next()) * side);
      const double blen = length * (0.35 + 0.2 * rng.next());
      const int steps = std::max(3, static_cast<int>(static_cast<double>(segs.size()) * 0.6));
      // Steps shrink by 0.9: their sum over `steps` is blen.
      const double first = blen * (1.0 - 0.9) / (1.0 - std::pow(0.9, steps));
      BoltBranch branch;
      branch.generation = g;
      branch.parent = parent_index;
      branch.segments = walk(start, bdir, first, 0.9, steps, 0.35,
                             parent.segments.front().radius * 0.5f, g, ground_y_m, rng);
      bolt.branches.push_back(std::move(branch));
    }
    parent_begin = child_begin;
    parent_count = counts[g];
  }
  return bolt;
}

namespace {

// Stroke j of a strike: when it starts (after the strike), how bright it peaks, and its decay
// time constant τ. The first starts at the strike; later ones in evenly spaced slots of 4τ,
// jittered by up to ±τ/2, so a stroke has decayed below e^−3 of its peak when the next begins.
struct Stroke {
  double start_s;
  double peak;
  double decay_s;
};

Stroke stroke(const LightningParams& params, int j, std::uint64_t seed, std::uint64_t strike) {
  const double duration = params.flash_duration_s;
  const int strokes = std::max(1, params.return_strokes);
  const double start =
      j == 0
          ? 0.0
          : duration * (j + 0.25 * (uniform(seed, Stream::bolt, strike, 1000 + j) - 0.5)) / strokes;
  const double peak = j == 0 ? 1.0 : 0.6 + 0.4 * uniform(seed, Stream::bolt, strike, 2000 + j);
  return {start, peak, duration / (4.0 * strokes)};
}

// ∫ of one stroke over [a, b] (times after the strike), the flash cut off at `duration`:
// peak · τ · (e^−(lo−start)/τ − e^−(hi−start)/τ) over [lo, hi] = [a, b] ∩ [start, duration].
double stroke_integral(const Stroke& s, double a, double b, double duration) {
  const double lo = std::max(a, s.start_s);
  const double hi = std::min(b, duration);
  if (!(hi > lo)) return 0.0;
  return s.peak * s.decay_s *
         (std::exp(-(lo - s.start_s) / s.decay_s) - std::exp(-(hi - s.start_s) / s.decay_s));
}

double stroke_value(const Stroke& s, double since, double duration) {
  if (since < s.start_s || since > duration) return 0.0;
  return s.peak * std::exp(-(since - s.start_s) / s.decay_s);
}

}  // namespace

double flash_envelope(const LightningParams& params, double since, std::uint64_t seed,
                      std::uint64_t strike) {
  const double duration = params.flash_duration_s;
  if (since < 0.0 || since > duration) return 0.0;
  double b = 0.0;
  for (int j = 0; j < std::max(1, params.return_strokes); ++j) {
    b += stroke_value(stroke(params, j, seed, strike), since, duration);
  }
  return b;
}

FlashExposure flash_exposure(const LightningParams& params, double since_open_s, double exposure_s,
                             std::uint64_t seed, std::uint64_t strike) {
  const double duration = params.flash_duration_s;
  FlashExposure out;
  for (int j = 0; j < std::max(1, params.return_strokes); ++j) {
    const Stroke s = stroke(params, j, seed, strike);
    const double light =
        exposure_s > 0.0
            ? stroke_integral(s, since_open_s, since_open_s + exposure_s, duration) / exposure_s
            : stroke_value(s, since_open_s, duration);
    out.all_strokes += light;
    if (j == 0) out.first_stroke = light;
  }
  return out;
}

double branch_brightness(int generation) {
  return generation <= 0 ? 1.0 : 0.35 * std::pow(0.5, generation - 1);
}

LightningSchedule::LightningSchedule(const LightningParams& params, std::uint64_t seed)
    : m_params(params), m_seed(seed) {}

std::vector<LightningSchedule::Strike> LightningSchedule::strikes_until(double t_s) {
  std::vector<Strike> out;
  if (!m_params.enabled) return out;
  if (m_params.first_strike_s >= 0.0 && m_params.first_strike_s <= t_s) {
    out.push_back({0, m_params.first_strike_s});
  }
  const double rate = m_params.strikes_per_minute / 60.0;
  if (rate > 0.0) {
    while (m_poisson.empty() || m_poisson.back() <= t_s) {
      const double previous = m_poisson.empty() ? 0.0 : m_poisson.back();
      m_poisson.push_back(previous +
                          exponential(m_seed, Stream::lightning, m_poisson.size() + 1) / rate);
    }
    for (std::size_t k = 0; k < m_poisson.size() && m_poisson[k] <= t_s; ++k) {
      out.push_back({k + 1, m_poisson[k]});
    }
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const Strike& a, const Strike& b) { return a.time_s < b.time_s; });
  return out;
}

}  // namespace raintrace::sim
