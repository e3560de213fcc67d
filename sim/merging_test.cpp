// Merging conserves water and momentum; the swept test catches overtaking drops.
#include "sim/merging.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/random.h"

namespace raintrace::sim {
namespace {

NewDrop drop(std::uint64_t id, glm::vec3 p, glm::vec3 v, float d) {
  NewDrop n;
  n.id = id;
  n.position = p;
  n.velocity = v;
  n.diameter = d;
  n.age = 1.0f;
  return n;
}

double volume_sum(const DropState& s) {
  double v = 0.0;
  for (const float d : s.drops.diameter) v += static_cast<double>(d) * d * d;
  return v;
}

TEST(Merging, TouchingDropsCoalesceConservingVolumeAndMomentum) {
  DropState s;
  s.push(drop(1, {0, 1, 0}, {0, -4, 0}, 1e-3f));
  s.push(drop(2, {0.0012f, 1, 0}, {1, -6, 0}, 2e-3f));  // centres 1.2 mm < (1+2)/2 mm
  s.push(drop(3, {1, 1, 1}, {0, -4, 0}, 1e-3f));        // far away
  std::uint64_t next = 10;
  const MergeResult r = merge_touching(s, 0.01f, 6.5e-3, next, 1);
  ASSERT_EQ(r.merges, 1u);
  ASSERT_EQ(s.size(), 2u);
  // Volume: 1³ + 2³ = 9 mm³-units → D = 9^(1/3) mm = 2.0801 mm.
  EXPECT_NEAR(s.drops.diameter[0], std::cbrt(9.0) * 1e-3, 1e-9);
  // Momentum: (1·(0,−4) + 8·(1,−6)) / 9 = (0.8889, −5.7778).
  EXPECT_NEAR(s.drops.velocity[0].x, 8.0 / 9.0, 1e-6);
  EXPECT_NEAR(s.drops.velocity[0].y, -52.0 / 9.0, 1e-5);
  EXPECT_EQ(s.drops.id[0], 2u);  // the larger drop keeps its identity
  EXPECT_EQ(s.drops.id[1], 3u);
}

TEST(Merging, FastDropOvertakingWithinTheIntervalIsCaught) {
  DropState s;
  // Now 3 cm apart vertically, closing at 3 m/s: 10 ms ago they were level → touched.
  s.push(drop(1, {0, 1.0f, 0}, {0, -2, 0}, 1e-3f));
  s.push(drop(2, {0, 0.985f, 0}, {0, -5, 0}, 1e-3f));
  std::uint64_t next = 10;
  // The lower one moved down faster, so going back in time they approach: gap at τ = −5 ms
  // is 0.015 − 3·0.005 = 0.
  EXPECT_EQ(merge_touching(s, 0.01f, 6.5e-3, next, 1).merges, 1u);
}

TEST(Merging, ManyDropsConserveTotalWater) {
  DropState s;
  for (std::uint64_t k = 0; k < 20000; ++k) {
    auto u = [&](int dim) { return static_cast<float>(uniform(5, Stream::fill, k, dim)); };
    s.push(drop(k, {u(0) * 0.5f, u(1) * 0.5f, u(2) * 0.5f}, {0, -2 - 6 * u(3), 0},
                (0.5f + 3.0f * u(4)) * 1e-3f));
  }
  const double before = volume_sum(s);
  std::uint64_t next = 20000;
  const MergeResult r = merge_touching(s, 0.01f, 6.5e-3, next, 1);
  EXPECT_GT(r.merges, 100u);  // 160 000 drops/m³: plenty of contacts
  EXPECT_NEAR(volume_sum(s), before, 1e-5 * before);
  for (const float d : s.drops.diameter) EXPECT_LE(d, 6.5e-3f);
}

TEST(Merging, SidewaysRelativeMotionWithinTheIntervalIsCaught) {
  DropState s;
  // A small drop lagging 1 m/s behind a gust relative to a large one (the thunderstorm's
  // measured spread): now 12 mm apart sideways, 10 ms ago 2 mm apart < 3 mm → they touched.
  s.push(drop(1, {0, 1, 0}, {3, -4, 0}, 1e-3f));
  s.push(drop(2, {0.012f, 1, 0}, {4, -4, 0}, 5e-3f));
  s.push(drop(3, {0.5f, 1, 0.5f}, {3.2f, -4, 0}, 1e-3f));  // far away
  std::uint64_t next = 10;
  MergeBounds b;
  EXPECT_EQ(merge_touching(s, 0.01f, 6.5e-3, next, 1, nullptr, 0.0, &b).merges, 1u);
  // The bound is measured from the drops: 1 m/s sideways, 0 vertically (plus margins).
  EXPECT_NEAR(b.dv_m_per_s.x, 1.0f, 0.02f);
  EXPECT_LT(b.dv_m_per_s.y, 0.01f);
  EXPECT_GE(b.touch_m, 5e-3f);
}

TEST(Merging, MergedDropPastCriticalDiameterBreaksUp) {
  DropState s;
  s.push(drop(1, {0, 1, 0}, {0, -9, 0}, 5.5e-3f));
  s.push(drop(2, {0.004f, 1, 0}, {0, -9, 0}, 5.5e-3f));  // 4 mm apart < 5.5 mm: touching
  const double before = volume_sum(s);
  std::uint64_t next = 10;
  const MergeResult r = merge_touching(s, 0.01f, 6.5e-3, next, 1);
  EXPECT_EQ(r.merges, 1u);
  EXPECT_EQ(r.breakups, 1u);
  // 2·5.5³ = 332.75 > 6.5³ = 274.6: the 6.93 mm drop breaks into ⌈2·332.75/274.6⌉ = 3.
  EXPECT_EQ(s.size(), 3u);
  EXPECT_NEAR(volume_sum(s), before, 1e-5 * before);
  for (const float d : s.drops.diameter) EXPECT_LT(d, 6.5e-3f);
}

}  // namespace
}  // namespace raintrace::sim
