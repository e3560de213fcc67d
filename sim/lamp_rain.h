// Rain beyond far_m where a lamp in view makes it show. A lamp lights the drops around it far
// more than any drop near the camera, and it backlights those between it and the camera: in a
// photograph of rain at night the streaks gather in the lamps' cones. Beyond far_m the rain is
// otherwise a smooth medium, so those streaks need drops. Simulating the whole view out to a
// lamp 22 m away costs ~50 times the default's 6 m of rain; LampRain simulates only the air
// around each lamp: for each, its own World of the same rain (rate, sizes, wind, seed mixed
// with the lamp's number, no merging), whose view is a narrow frustum from the camera just wide
// enough for a ball of radius lamp_reach_m below and in front of the lamp (the air it lights
// and backlights), with nothing on the ground (no splashes, ripples, puddles or lightning). Its
// drops inside that ball, inside the camera's view and beyond far_m (where the main World's
// stop) join the frame's.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/frame.h"
#include "sim/params.h"
#include "sim/view_volume.h"
#include "sim/world.h"

namespace raintrace::sim {

class LampRain {
 public:
  /// Drop ids of lamp k's World are offset by (k + 1)·kIdStride, so they never meet the main
  /// World's (which would need 2^40 drops) or another lamp's.
  static constexpr std::uint64_t kIdStride = std::uint64_t{1} << 40;

  /// The lamps of params.lamps whose lens is in the camera's view between rain.far_m and
  /// rain.lamp_far_m and whose ball (radius rain.lamp_reach_m) leaves the eye out take part;
  /// lamp_reach_m = 0 or no lamp: none. Throws std::invalid_argument like World for bad params.
  explicit LampRain(const SimParams& params, const std::atomic<bool>* cancel = nullptr);

  /// What the lamps' Worlds simulate, summed (World::estimate of each). drops_in_view stays 0:
  /// how many of their drops a frame draws is what sample() is for. Cheap.
  static WorkEstimate estimate(const SimParams& params);

  /// For budgets (output/budget.h): which of the lamps' drops a frame draws depends on how far
  /// and how large they are (povgen thins faint far streaks), which a sample measures. Here
  /// `per_lamp` drops of the rain's sizes spread evenly through each lamp's ball, falling at
  /// their terminal speed in the steady wind, those add_drops would keep; each stands for
  /// `drops_per_sample` drops of the rain. Cheap, and the same for the same params.
  struct Sample {
    Drops drops;
    double drops_per_sample = 0.0;
  };
  static Sample sample(const SimParams& params, int per_lamp);

  /// How many lamps take part.
  [[nodiscard]] std::size_t lamp_count() const { return m_lamps.size(); }
  /// Drops their Worlds hold, in view or not.
  [[nodiscard]] std::size_t simulated_drops() const;
  /// Advances every lamp's World (World::advance_to).
  void advance_to(double t_s);
  /// Appends the drops now in every lamp's ball (in view, beyond far_m) to drops, in lamp
  /// order, each World's in its own order.
  void add_drops(Drops& drops) const;

 private:
  struct Lamp {
    glm::dvec3 centre{};  // of the ball of rain drawn
    std::unique_ptr<World> world;
  };
  std::vector<Lamp> m_lamps;
  ViewVolume m_beyond;  // the camera's view from far_m out to the farthest ball
  double m_reach_m = 0.0;
};

}  // namespace raintrace::sim
