// One snapshot of the simulated world: what the exporter turns into a POV-Ray frame.
// Structure of arrays so that writers and the integrator walk contiguous memory.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace raintrace::sim {

/// Falling drops; index i across all vectors is one drop. Positions in metres, SI throughout.
struct Drops {
  std::vector<std::uint64_t> id;        ///< stable identity while the drop lives
  std::vector<glm::vec3> position;      ///< m
  std::vector<glm::vec3> velocity;      ///< m/s
  std::vector<glm::vec3> acceleration;  ///< m/s², from the last substep
  std::vector<float> diameter;          ///< m, equivalent-volume diameter
  std::vector<float> age;               ///< s since the drop was born (the paper's lifetime)
  std::vector<float> vanishing_rate;    ///< 1/s
  std::vector<float> opacity;           ///< 0..1, falls with vanishing
  std::vector<glm::vec3> colour;        ///< linear RGB tint

  [[nodiscard]] std::size_t size() const { return id.size(); }
  /// Appends a copy of drop i of `from`, every field.
  void append(const Drops& from, std::size_t i) {
    id.push_back(from.id[i]);
    position.push_back(from.position[i]);
    velocity.push_back(from.velocity[i]);
    acceleration.push_back(from.acceleration[i]);
    diameter.push_back(from.diameter[i]);
    age.push_back(from.age[i]);
    vanishing_rate.push_back(from.vanishing_rate[i]);
    opacity.push_back(from.opacity[i]);
    colour.push_back(from.colour[i]);
  }
};

/// Ring ripples spreading on standing water from one impact (sim/ripples.h draws them).
struct Ripple {
  float x = 0.0f, z = 0.0f;     ///< m, where the drop hit the ground
  float age_s = 0.0f;           ///< s since the impact
  float lifetime_s = 0.0f;      ///< s until the ring has faded out (0: no ripple)
  float amplitude_m = 0.0f;     ///< height of the first crest as it leaves the crater
  float start_radius_m = 0.0f;  ///< where the ring starts, about a drop diameter out
  bool on_puddle = true;        ///< rings on a puddle; false: the thin film's brief ones

  // Compared member by member: the struct has padding after on_puddle, which memcmp would read.
  bool operator==(const Ripple&) const = default;
};

struct BoltSegment {
  glm::vec3 start;  ///< m
  glm::vec3 end;    ///< m
  float radius;     ///< m
  int generation;   ///< 0 = trunk, 1 = branch, 2 = sub-branch, …
};

/// One lightning bolt: an L-system skeleton and how bright it is in this frame.
struct Bolt {
  std::vector<BoltSegment> segments;
  /// The main channel: the flash envelope (all return strokes, ~0..1) averaged over the frame's
  /// exposure; also the bolt's light on the scene.
  float brightness = 0.0f;
  /// The first return stroke alone, averaged the same way: the branches glow with it only
  /// (times sim::branch_brightness(generation)).
  float branch_brightness = 0.0f;
  std::uint64_t id = 0;  ///< strike number (0-based, in strike order), stable across frames
};

struct Frame {
  int index = 0;        ///< 1-based frame number
  double time_s = 0.0;  ///< simulated time of the snapshot
  Drops drops;
  /// Crown-splash droplets in flight, as drops: ids stable over their flight; opacity may
  /// exceed 1 — it carries the level-of-detail weight of their impact (1/p of its keeping).
  Drops splashes;
  /// Ripples still spreading where a pixel is small enough to show their rings (sim/ripples.h);
  /// farther ones are drawn as the roughness they add (ripple_slope_rms()).
  std::vector<Ripple> ripples;
  std::vector<Bolt> bolts;       ///< bolts visible at this instant
  float flash = 0.0f;            ///< 0..1, total lightning light on the scene in this frame
  glm::vec3 wind_m_per_s{0.0f};  ///< wind at the camera's look-at point

  // Running totals since t = 0 (prewarm excluded), for statistics; added by sim/.
  double ground_water_m3 = 0.0;   ///< water volume of drops that reached the measured ground
  double ground_area_m2 = 0.0;    ///< ground area over which ground_water_m3 is measured
  std::uint64_t ground_hits = 0;  ///< drops that reached the ground anywhere in the volume
  /// Drops that reached the visible ground (the volume's footprint and the sampled ground beyond
  /// it), splashes among them and impacts on puddles (which start ripples). Weighted by the
  /// level of detail, so each is an estimate of the real number; the _simulated counts are
  /// the impacts actually simulated.
  double ground_impacts = 0.0;
  double splash_events = 0.0;
  double ripple_events = 0.0;
  std::uint64_t ground_impacts_simulated = 0;
  double impact_area_m2 = 0.0;  ///< ground the impacts are counted over (footprint + sampled), m²
  std::uint64_t lightning_strikes = 0;  ///< strikes started at or before time_s
  double view_volume_m3 = 0.0;          ///< volume of the view frustum [near_m, far_m] drops fill
};

}  // namespace raintrace::sim
