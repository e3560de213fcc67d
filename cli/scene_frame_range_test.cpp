// Tests for `--frames` parsing.
#include <gtest/gtest.h>
#include <stdexcept>

#include "cli/scene.h"

namespace raintrace::cli {
namespace {

TEST(ParseFrameRange, EmptyMeansAllFrames) {
  const FrameRange range = parse_frame_range("", 48);
  EXPECT_EQ(range.first, 1);
  EXPECT_EQ(range.last, 48);
}

TEST(ParseFrameRange, SingleNumberIsOneFrame) {
  const FrameRange range = parse_frame_range("7", 48);
  EXPECT_EQ(range.first, 7);
  EXPECT_EQ(range.last, 7);
}

TEST(ParseFrameRange, RangeIsInclusive) {
  const FrameRange range = parse_frame_range("3-48", 48);
  EXPECT_EQ(range.first, 3);
  EXPECT_EQ(range.last, 48);
}

TEST(ParseFrameRange, RejectsOutOfRangeAndReversed) {
  EXPECT_THROW(parse_frame_range("0", 48), std::invalid_argument);
  EXPECT_THROW(parse_frame_range("49", 48), std::invalid_argument);
  EXPECT_THROW(parse_frame_range("1-49", 48), std::invalid_argument);
  EXPECT_THROW(parse_frame_range("10-5", 48), std::invalid_argument);
}

TEST(ParseFrameRange, RejectsMalformedText) {
  for (const char* text :
       {"-", "-5", "5-", "+3", "a", "1-2-3", " 1", "1 ", "1.5", "1--2", "99999999999999999999"}) {
    EXPECT_THROW(parse_frame_range(text, 48), std::invalid_argument) << text;
  }
}

TEST(ParseFrameRange, MessageNamesTheOptionAndTheValidFrames) {
  try {
    parse_frame_range("60", 48);
    FAIL() << "expected an exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--frames"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("1-48"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace raintrace::cli
