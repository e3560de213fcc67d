// Breakup past the critical diameter.
#include "sim/breakup.h"

#include <gtest/gtest.h>

namespace raintrace::sim {
namespace {

TEST(Breakup, LargeDropSplitsConservingVolume) {
  DropState s;
  NewDrop d;
  d.id = 7;
  d.diameter = 8e-3f;
  d.velocity = {0, -9, 0};
  s.push(d);
  std::uint64_t next = 100;
  // 2·8³/6.5³ = 3.73 → 4 fragments.
  EXPECT_EQ(break_up(s, 0, 6.5e-3, next, 1), 3u);
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s.drops.id[0], 7u);
  EXPECT_EQ(next, 103u);
  double volume = 0.0;
  for (const float f : s.drops.diameter) {
    EXPECT_LT(f, 6.5e-3f);
    EXPECT_GT(f, 3e-3f);  // jittered around (512/4)^(1/3) = 5.04 mm
    volume += static_cast<double>(f) * f * f;
  }
  EXPECT_NEAR(volume, 512e-9, 1e-5 * 512e-9);
  // Fragment drag follows its new size (smaller drop → larger k = g/v²).
  EXPECT_GT(s.drag[0], 0.0f);
}

TEST(Breakup, SmallDropIsLeftAlone) {
  DropState s;
  NewDrop d;
  d.diameter = 3e-3f;
  s.push(d);
  std::uint64_t next = 0;
  EXPECT_EQ(break_up(s, 0, 6.5e-3, next, 1), 0u);
  EXPECT_EQ(s.size(), 1u);
  EXPECT_EQ(s.drops.diameter[0], 3e-3f);
}

}  // namespace
}  // namespace raintrace::sim
