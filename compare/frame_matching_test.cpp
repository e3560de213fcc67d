// Frame pairing by name.
#include "compare/frame_matching.h"

#include <gtest/gtest.h>

namespace raintrace::compare {
namespace {

TEST(FrameMatching, UnionSortedWithSidesFlagged) {
  const auto pairs = match_frames({"frame_0002.png", "frame_0001.png", "frame_0004.png"},
                                  {"frame_0003.png", "frame_0001.png", "frame_0002.png"});
  ASSERT_EQ(pairs.size(), 4u);
  EXPECT_EQ(pairs[0].name, "frame_0001.png");
  EXPECT_TRUE(pairs[0].in_a && pairs[0].in_b);
  EXPECT_TRUE(pairs[1].in_a && pairs[1].in_b);
  EXPECT_EQ(pairs[2].name, "frame_0003.png");
  EXPECT_TRUE(!pairs[2].in_a && pairs[2].in_b);
  EXPECT_EQ(pairs[3].name, "frame_0004.png");
  EXPECT_TRUE(pairs[3].in_a && !pairs[3].in_b);
}

TEST(FrameMatching, EmptySidesAndDuplicates) {
  EXPECT_TRUE(match_frames({}, {}).empty());
  const auto pairs = match_frames({"a.png", "a.png"}, {});
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_FALSE(pairs[0].in_b);
}

}  // namespace
}  // namespace raintrace::compare
