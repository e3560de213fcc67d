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
};

/// Short-lived ballistic droplets thrown up where drops hit the ground.
struct SplashDroplets {
  std::vector<glm::vec3> position;  ///< m
  std::vector<glm::vec3> velocity;  ///< m/s
  std::vector<float> diameter;      ///< m
  std::vector<float> opacity;       ///< 0..1, fades over the droplet's life

  [[nodiscard]] std::size_t size() const { return position.size(); }
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
  SplashDroplets splashes;
  std::vector<Bolt> bolts;       ///< bolts visible at this instant
  float flash = 0.0f;            ///< 0..1, total lightning light on the scene in this frame
  glm::vec3 wind_m_per_s{0.0f};  ///< wind at the camera's look-at point

  // Running totals since t = 0 (prewarm excluded), for statistics; added by sim/.
  double ground_water_m3 = 0.0;         ///< water volume of drops that reached the measured ground
  double ground_area_m2 = 0.0;          ///< ground area over which ground_water_m3 is measured
  std::uint64_t ground_hits = 0;        ///< drops that reached the ground anywhere in the volume
  std::uint64_t splash_events = 0;      ///< ground hits inside the view that threw droplets
  std::uint64_t lightning_strikes = 0;  ///< strikes started at or before time_s
  double view_volume_m3 = 0.0;          ///< volume of the view frustum [near_m, far_m] drops fill
};

}  // namespace raintrace::sim
