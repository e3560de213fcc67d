// The integrator against the wind field it is given: each drop is dragged toward exactly the wind
// Wind::at reports at its position, turbulence included (the block loop and Wind::at share
// turbulence_of, and this keeps them from drifting apart).
#include "sim/integrator.h"

#include <gtest/gtest.h>
#include <cmath>

#include "sim/random.h"
#include "sim/terminal_velocity.h"

namespace raintrace::sim {
namespace {

TEST(Integrator, DragsEachDropTowardTheWindThatWindAtReports) {
  WindParams params;
  params.velocity_m_per_s = {1.5, 0.0, -0.5};
  params.gusts = true;
  params.turbulence_m_per_s = 3.0;
  params.turbulence_scale_m = 2.0;
  const Wind wind(params, 5);
  ASSERT_TRUE(wind.has_turbulence());

  // 300 drops: more than one of the integrator's blocks of 256.
  DropState state;
  for (std::uint64_t i = 0; i < 300; ++i) {
    NewDrop d;
    d.id = i;
    d.position = {static_cast<float>(8 * uniform(1, Stream::fill, i, 0) - 4),
                  static_cast<float>(1 + 4 * uniform(1, Stream::fill, i, 1)),
                  static_cast<float>(8 * uniform(1, Stream::fill, i, 2))};
    d.velocity = {0.3f, -static_cast<float>(i % 7), 0.1f};
    d.diameter = static_cast<float>(0.5e-3 + 3e-3 * uniform(1, Stream::fill, i, 3));
    state.push(d);
  }
  const DropState before = state;

  StepConstants c;
  c.dt = 0.002f;
  c.time_s = 0.37;
  c.wind = glm::vec3(wind.uniform_at(c.time_s));
  c.turbulence = &wind;
  // A box and footprint far larger than the drops' reach: nobody leaves.
  c.a0 = c.b0 = c.fa0 = c.fb0 = -1e4f;
  c.a1 = c.b1 = c.fa1 = c.fb1 = 1e4f;
  c.ground = -1e4f;
  c.ceiling = 1e4f;
  StepEvents events;
  integrate_range(state, 0, state.size(), c, events);
  EXPECT_TRUE(events.ground.empty());
  EXPECT_TRUE(events.gone.empty());

  for (std::size_t i = 0; i < state.size(); ++i) {
    // The implicit drag step of integrator.h with the wind Wind::at gives at the drop.
    const glm::vec3 w = wind.at(before.drops.position[i], c.time_s);
    const glm::vec3 v = before.drops.velocity[i];
    const glm::vec3 u = w - v;
    const float ku = before.drag[i] * std::sqrt(u.x * u.x + u.y * u.y + u.z * u.z);
    const float inv = 1.0f / (1.0f + ku * c.dt);
    const glm::vec3 expected{(v.x + c.dt * ku * w.x) * inv,
                             (v.y + c.dt * (ku * w.y - static_cast<float>(kGravity))) * inv,
                             (v.z + c.dt * ku * w.z) * inv};
    const glm::vec3 got = state.drops.velocity[i];
    EXPECT_FLOAT_EQ(got.x, expected.x) << "drop " << i;
    EXPECT_FLOAT_EQ(got.y, expected.y) << "drop " << i;
    EXPECT_FLOAT_EQ(got.z, expected.z) << "drop " << i;
  }
  // The turbulence is really there: the field differs from drop to drop by more than the
  // tolerance above.
  const glm::vec3 t0 = wind.turbulence_at(before.drops.position[0], c.time_s);
  const glm::vec3 t1 = wind.turbulence_at(before.drops.position[1], c.time_s);
  EXPECT_GT(std::fabs(t0.x - t1.x) + std::fabs(t0.z - t1.z), 0.1f);
}

}  // namespace
}  // namespace raintrace::sim
