// Span cutting.
#include "render/spans.h"

#include <gtest/gtest.h>

namespace raintrace::render {
namespace {

std::vector<int> iota(int first, int last) {
  std::vector<int> v;
  for (int i = first; i <= last; ++i) v.push_back(i);
  return v;
}

TEST(SplitIntoSpans, GivesEachJobAboutTwoSpansCappedAtMaxSpan) {
  // 48 frames, 2 jobs: ceil(48 / 4) = 12 frames per span → 4 spans.
  const auto spans = split_into_spans(iota(1, 48), 2, 16);
  ASSERT_EQ(spans.size(), 4U);
  EXPECT_EQ(spans[0].first, 1);
  EXPECT_EQ(spans[0].last, 12);
  EXPECT_EQ(spans[3].last, 48);
  // 1000 frames: capped at 12 → ceil(1000 / 12) = 84 spans.
  EXPECT_EQ(split_into_spans(iota(1, 1000), 2, 12).size(), 84U);
}

TEST(SplitIntoSpans, NeverBridgesAGap) {
  const auto spans = split_into_spans({1, 2, 3, 7, 8}, 1, 16);
  ASSERT_EQ(spans.size(), 2U);
  EXPECT_EQ(spans[0].last, 3);
  EXPECT_EQ(spans[1].first, 7);
  EXPECT_EQ(spans[1].last, 8);
}

TEST(SplitIntoSpans, CoversEveryFrameExactlyOnce) {
  const auto frames = std::vector<int>{2, 3, 4, 5, 9, 10, 11, 20, 21, 22, 23, 24, 25, 26, 40};
  std::vector<int> covered;
  for (const auto& s : split_into_spans(frames, 3, 4)) {
    EXPECT_LE(s.count(), 4);
    for (int f = s.first; f <= s.last; ++f) covered.push_back(f);
  }
  EXPECT_EQ(covered, frames);
}

TEST(StreamingSpanLength, MatchesTheSplitOfTheWholeRun) {
  EXPECT_EQ(streaming_span_length(48, 2, 16), 12);  // ceil(48 / (2·2)), as split_into_spans
  EXPECT_EQ(streaming_span_length(48, 1, 12), 12);  // 24 capped at max_span
  EXPECT_EQ(streaming_span_length(8, 3, 12), 2);    // ceil(8 / 6)
  EXPECT_EQ(streaming_span_length(0, 2, 12), 1);
}

TEST(StreamingSpans, ARunStartsOnceItIsLongEnoughNotBefore) {
  StreamingSpans plan{3};
  plan.arrived(1, true);
  plan.arrived(2, true);
  EXPECT_FALSE(plan.take_ready());  // frame 3 may still join this span
  plan.arrived(3, true);
  const auto span = plan.take_ready();
  ASSERT_TRUE(span);
  EXPECT_EQ(span->first, 1);
  EXPECT_EQ(span->last, 3);
  EXPECT_FALSE(plan.take_ready());
  EXPECT_FALSE(plan.exhausted());
}

TEST(StreamingSpans, AShortRunIsReadyWhenTheFrameAfterItNeedsNoRender) {
  StreamingSpans plan{4};
  plan.arrived(1, true);
  plan.arrived(2, true);
  EXPECT_FALSE(plan.take_ready());
  plan.arrived(3, false);  // up to date: frames 1-2 can never grow into a longer span
  const auto span = plan.take_ready();
  ASSERT_TRUE(span);
  EXPECT_EQ(span->first, 1);
  EXPECT_EQ(span->last, 2);
  plan.arrived(4, true);
  plan.arrived(6, true);  // 5 was skipped (not in this run): 4 alone is final
  const auto four = plan.take_ready();
  ASSERT_TRUE(four);
  EXPECT_EQ(four->first, 4);
  EXPECT_EQ(four->last, 4);
  EXPECT_FALSE(plan.take_ready());  // 6 may still grow
}

TEST(StreamingSpans, ClosingCutsThePendingTailIntoAPiecePerJob) {
  StreamingSpans plan{12};
  for (int f = 1; f <= 7; ++f) plan.arrived(f, true);
  EXPECT_FALSE(plan.take_ready());
  plan.close(3);  // 7 frames, 3 jobs: spans of ceil(7 / 3) = 3 → 1-3, 4-6, 7
  std::vector<std::pair<int, int>> spans;
  while (const auto s = plan.take_ready()) spans.emplace_back(s->first, s->last);
  EXPECT_EQ(spans, (std::vector<std::pair<int, int>>{{1, 3}, {4, 6}, {7, 7}}));
  EXPECT_TRUE(plan.exhausted());
  plan.arrived(8, true);  // nothing arrives after close
  EXPECT_TRUE(plan.exhausted());
}

TEST(StreamingSpans, CoversEveryFrameThatNeedsARenderExactlyOnce) {
  StreamingSpans plan{4};
  std::vector<int> expected;
  std::vector<int> covered;
  auto drain = [&] {
    while (const auto s = plan.take_ready()) {
      EXPECT_LE(s->count(), 4);
      for (int f = s->first; f <= s->last; ++f) covered.push_back(f);
    }
  };
  for (int f = 1; f <= 30; ++f) {
    const bool needs = f % 7 != 0 && f % 11 != 0;
    if (needs) expected.push_back(f);
    plan.arrived(f, needs);
    drain();
  }
  plan.close(2);
  drain();
  EXPECT_EQ(covered, expected);
  EXPECT_TRUE(plan.exhausted());
}

}  // namespace
}  // namespace raintrace::render
