// Terminal velocity against Gunn & Kinzer (1949), and the integrator converging to it.
#include "sim/terminal_velocity.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/drop_state.h"
#include "sim/integrator.h"

namespace raintrace::sim {
namespace {

// Gunn & Kinzer (1949), Table 2: diameter (mm) → terminal velocity (m/s), still air at sea level.
struct Measured {
  double d_mm, v;
};
constexpr Measured kGunnKinzer[] = {{0.5, 2.06}, {0.6, 2.47}, {0.8, 3.27}, {1.0, 4.03},
                                    {1.4, 5.17}, {2.0, 6.49}, {2.6, 7.57}, {3.0, 8.06},
                                    {3.6, 8.60}, {4.0, 8.83}, {4.6, 9.03}, {5.0, 9.09}};

TEST(TerminalVelocity, MatchesGunnKinzerWithinFivePercent) {
  for (const auto& m : kGunnKinzer) {
    EXPECT_NEAR(terminal_velocity(m.d_mm * 1e-3), m.v, 0.05 * m.v) << m.d_mm << " mm";
  }
}

TEST(TerminalVelocity, SmallDropsFollowTheTableToo) {
  // Gunn & Kinzer: 0.1 mm 0.27 m/s, 0.2 mm 0.72, 0.3 mm 1.17, 0.4 mm 1.62 — the linear piece
  // from (0.1, 0.27) to Atlas at 0.5 mm (2.019) gives 0.707, 1.145, 1.582: within 3 %.
  EXPECT_NEAR(terminal_velocity(0.2e-3), 0.72, 0.03 * 0.72);
  EXPECT_NEAR(terminal_velocity(0.3e-3), 1.17, 0.03 * 1.17);
  EXPECT_NEAR(terminal_velocity(0.4e-3), 1.62, 0.03 * 1.62);
  EXPECT_DOUBLE_EQ(terminal_velocity(0.0), 0.0);
}

TEST(TerminalVelocity, IsContinuousAndIncreasing) {
  double previous = 0.0;
  for (double d = 0.01e-3; d <= 8e-3; d += 0.01e-3) {
    const double v = terminal_velocity(d);
    EXPECT_GT(v, previous) << d;
    EXPECT_LT(v - previous, 0.1) << "jump at " << d;
    previous = v;
  }
}

TEST(TerminalVelocity, DragBalancesGravityAtTerminalSpeed) {
  for (const double d : {0.5e-3, 2e-3, 5e-3}) {
    const double v = terminal_velocity(d);
    EXPECT_NEAR(drag_coefficient(d) * v * v, kGravity, 1e-9);
  }
}

// Integrates one drop released at rest in `wind` for `seconds` with substep dt.
glm::vec3 release(double d, glm::vec3 wind, float dt, double seconds) {
  DropState s;
  NewDrop drop;
  drop.diameter = static_cast<float>(d);
  drop.position = {0.0f, 1.0e4f, 0.0f};
  s.push(drop);
  StepConstants c;
  c.dt = dt;
  c.wind = wind;
  c.a0 = c.b0 = -1e9f;
  c.a1 = c.b1 = 1e9f;
  c.ground = -1e9f;
  c.ceiling = 1e9f;
  StepEvents events;
  const int steps = static_cast<int>(seconds / dt);
  for (int k = 0; k < steps; ++k) integrate_range(s, 0, 1, c, events);
  return s.drops.velocity[0];
}

TEST(Drag, DropsReleasedAtRestReachTheirMeasuredTerminalVelocity) {
  // The relaxation time is v_t/g < 1 s; after 10 s the drop is at v_t to float precision.
  for (const auto& m : kGunnKinzer) {
    for (const float dt : {1e-4f, 0.002f, 0.02f}) {
      const glm::vec3 v = release(m.d_mm * 1e-3, glm::vec3{0.0f}, dt, 10.0);
      EXPECT_NEAR(-v.y, m.v, 0.05 * m.v) << m.d_mm << " mm, dt " << dt;
      // To float precision: 100 000 substeps of 1e-4 s accumulate rounding of ~0.1 %.
      EXPECT_NEAR(-v.y, terminal_velocity(m.d_mm * 1e-3), 1e-3 * m.v) << m.d_mm << " mm, dt " << dt;
    }
  }
}

TEST(Drag, DropsDriftWithTheWindHorizontally) {
  const glm::vec3 wind{6.0f, 0.0f, -3.0f};
  const glm::vec3 v = release(2e-3, wind, 0.002f, 10.0);
  EXPECT_NEAR(v.x, 6.0f, 1e-3);
  EXPECT_NEAR(v.z, -3.0f, 1e-3);
  // Relative to the air it still falls at its terminal speed.
  EXPECT_NEAR(-v.y, terminal_velocity(2e-3), 1e-3);
}

TEST(Drag, StableAtTheLargestSubstepForTheSmallestDrop) {
  // 0.1 mm: relaxation time 0.027 s, close to the 0.02 s substep — explicit Euler would ring.
  const glm::vec3 v = release(0.1e-3, glm::vec3{30.0f, 0.0f, 0.0f}, 0.02f, 2.0);
  EXPECT_TRUE(std::isfinite(v.x) && std::isfinite(v.y));
  EXPECT_NEAR(v.x, 30.0f, 1e-2);
  EXPECT_NEAR(-v.y, terminal_velocity(0.1e-3), 1e-2);
}

}  // namespace
}  // namespace raintrace::sim
