// Where water stands on the ground: a procedural puddle field shared by the simulation (an
// impact on a puddle makes rings and needs a bigger drop to splash) and the renderer (povgen
// draws the same puddles).
//
// The field is a sum of cosines with random directions and phases, f(x, z) = Σ a·cos(k·p + φ),
// in three bands around k0 = π/size_m (broad wet and drier areas at k0/3, puddles at k0, ragged
// edges at 2.5·k0), scaled to unit variance: with dozens of terms it is close to a Gaussian
// random field, smooth, unbounded and cheap. Water stands where f exceeds the threshold that
// leaves `coverage` of the ground under it, measured on the field itself. Depth grows from the
// film thickness at the edge to depth_mm over 0.4 standard deviations of f.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/params.h"

namespace raintrace::sim {

class PuddleField {
 public:
  /// One cosine term: amplitude·cos(kx·x + kz·z + phase).
  struct Wave {
    double kx = 0.0, kz = 0.0;  ///< 1/m
    double phase = 0.0;         ///< radians
    double amplitude = 0.0;
  };

  /// Coverage <= 0 (or < 0, "the environment's default", left unresolved): no puddles.
  PuddleField(const PuddleParams& params, std::uint64_t seed);

  /// The field value at ground point (x, z); puddles where it exceeds threshold().
  [[nodiscard]] double value(double x, double z) const;
  /// True if (x, z) lies under standing water.
  [[nodiscard]] bool in_puddle(double x, double z) const;
  /// Water depth at (x, z), m: params.film_mm outside puddles, up to params.depth_mm inside.
  [[nodiscard]] double depth_m(double x, double z) const;
  /// depth_m() and in_puddle() with one evaluation of the field.
  struct Water {
    double depth_m = 0.0;
    bool puddle = false;
  };
  [[nodiscard]] Water water_at(double x, double z) const;
  /// Half the width of the band around a puddle's edge that share() spans, on the ground.
  static constexpr double kFringeM = 0.25;
  /// The field's level across a puddle's edge for drawing, 0..1: 0.5 on the edge, rising
  /// linearly from 0 to 1 over ±kFringeM (on average: the field's rms slope across an edge), so
  /// >= 0.5 exactly where in_puddle(). The renderer draws the shoreline within that band, where
  /// the level beats the road's own relief (templates/raintrace_ground.inc).
  [[nodiscard]] double share(double x, double z) const;

  [[nodiscard]] bool empty() const { return m_waves.empty(); }
  [[nodiscard]] const std::vector<Wave>& waves() const { return m_waves; }
  [[nodiscard]] double threshold() const { return m_threshold; }
  /// share()'s half width in units of the field: kFringeM times its rms slope in one direction.
  [[nodiscard]] double edge() const { return m_edge; }

 private:
  std::vector<Wave> m_waves;
  double m_threshold = 0.0;
  double m_edge = 0.0;
  double m_film_m = 0.0;
  double m_depth_m = 0.0;
};

}  // namespace raintrace::sim
