// The ETA from the POV-Ray processes' pace.
#include "render/render_pace.h"

#include <gtest/gtest.h>

#include <thread>

#include "render/progress.h"

namespace raintrace::render {
namespace {

using Clock = RenderPace::Clock;
using std::chrono::seconds;

// Twelve frames in four processes of three, all started at t0.
RenderPace four_processes_on_twelve_frames(Clock::time_point t0) {
  RenderPace pace{t0};
  for (const int first : {1, 4, 7, 10}) pace.started(Pass::image, {first, first + 2}, t0);
  return pace;
}

TEST(RenderPace, HasNoEstimateBeforeAPictureFinishes) {
  const auto t0 = Clock::now();
  const RenderPace pace = four_processes_on_twelve_frames(t0);
  EXPECT_FALSE(pace.seconds_left(12, t0 + seconds(60)).has_value());
}

TEST(RenderPace, CountsTheFirstBatchsOtherPicturesAsNearlyDone) {
  const auto t0 = Clock::now();
  RenderPace pace = four_processes_on_twelve_frames(t0);
  pace.finished(Pass::image, 1, t0 + seconds(96));
  // Four shared the machine for 96 s: frame 1 cost 24 s of it, and frames 4, 7 and 10 have had
  // as much (0 left). Frame 2 has just started (24 s left); 11 untraced − 4 in flight = 7 queued
  // at 24 s: 24 + 7·24 = 192 s, where the plain rate says 96 / 1 × 11 = 1056 s.
  const auto left = pace.seconds_left(11, t0 + seconds(96));
  ASSERT_TRUE(left.has_value());
  EXPECT_DOUBLE_EQ(*left, 192.0);
}

TEST(RenderPace, FallsWithTheClockWhileEveryProcessIsBusy) {
  const auto t0 = Clock::now();
  RenderPace pace = four_processes_on_twelve_frames(t0);
  for (const int frame : {1, 4, 7, 10}) pace.finished(Pass::image, frame, t0 + seconds(100));
  // Each cost 25 s of the machine. Four in flight, just started, and 4 queued: 8·25 = 200 s,
  // and ten seconds later ten less (the plain rate grows instead: 100/4·8, then 110/4·8).
  EXPECT_DOUBLE_EQ(*pace.seconds_left(8, t0 + seconds(100)), 200.0);
  EXPECT_DOUBLE_EQ(*pace.seconds_left(8, t0 + seconds(110)), 190.0);
}

TEST(RenderPace, ALonePictureGetsTheWholeMachine) {
  const auto t0 = Clock::now();
  RenderPace pace{t0};
  pace.started(Pass::image, {1, 2}, t0);
  pace.started(Pass::image, {3, 3}, t0);
  pace.finished(Pass::image, 1, t0 + seconds(40));  // 20 s of the machine
  pace.finished(Pass::image, 3, t0 + seconds(40));  // 20 s; frame 2 alone from here
  // Frame 2 alone for 15 s has had 15 of its 20: 5 s left, not (20 − 7.5) at half the machine.
  EXPECT_DOUBLE_EQ(*pace.seconds_left(1, t0 + seconds(55)), 5.0);
}

TEST(RenderPace, AFailedPictureLeavesTheFlightAndTheRestOfItsSpanStartsAnew) {
  const auto t0 = Clock::now();
  RenderPace pace{t0};
  pace.started(Pass::image, {1, 3}, t0);
  pace.started(Pass::mask, {1, 3}, t0);
  pace.finished(Pass::mask, 1, t0 + seconds(20));  // 10 s of the machine
  pace.failed(Pass::image, 1, t0 + seconds(20));
  EXPECT_EQ(pace.finished_count(), 1);
  // In flight: mask 2 alone (10 s left); images 2, 3 and mask 3 queued: 10 + 3·10 = 40 s.
  EXPECT_DOUBLE_EQ(*pace.seconds_left(4, t0 + seconds(20)), 40.0);
  pace.started(Pass::image, {2, 3}, t0 + seconds(20));
  // Image 2 in flight as well; five seconds later each has had 2.5 s: 2·7.5 + 2·10 = 35 s.
  EXPECT_DOUBLE_EQ(*pace.seconds_left(4, t0 + seconds(25)), 35.0);
}

TEST(RenderPace, TheMeanIsTheLatestFinishedPicturesOnly) {
  const auto t0 = Clock::now();
  RenderPace pace{t0};
  // One process, sixteen frames: eight cost 20 s each (beside an exporter, say), then eight
  // cost 10 s. The mean is the last eight's, 10 s: frame 17 is just starting, 10 s left.
  pace.started(Pass::image, {1, 17}, t0);
  int t = 0;
  for (int frame = 1; frame <= 16; ++frame) {
    t += frame <= 8 ? 20 : 10;
    pace.finished(Pass::image, frame, t0 + seconds(t));
  }
  EXPECT_EQ(pace.finished_count(), 16);
  EXPECT_DOUBLE_EQ(*pace.seconds_left(1, t0 + seconds(t)), 10.0);
}

TEST(RenderPace, BeforeAnyPictureFinishesAPictureTracingHasAPaceOfItsOwn) {
  const auto t0 = Clock::now();
  RenderPace pace{t0};
  pace.started(Pass::image, {1, 3}, t0);
  // POV-Ray parsed for 2 s, then showed 2 % traced: no rate yet.
  pace.traced(Pass::image, 1, 0.02, t0 + seconds(2));
  EXPECT_FALSE(pace.seconds_left(3, t0 + seconds(2)).has_value());
  // 52 % five seconds later: 10 % a second, so 4.8 s left of a picture that costs 7 + 4.8; two
  // more like it queued: 4.8 + 2·11.8 = 28.4 s. A second on, one less.
  pace.traced(Pass::image, 1, 0.52, t0 + seconds(7));
  EXPECT_DOUBLE_EQ(*pace.seconds_left(3, t0 + seconds(7)), 28.4);
  EXPECT_DOUBLE_EQ(*pace.seconds_left(3, t0 + seconds(8)), 27.4);
}

TEST(RenderPace, APictureTracingSlowerThanTheMeanIsGivenItsOwnRate) {
  const auto t0 = Clock::now();
  RenderPace pace{t0};
  pace.started(Pass::image, {1, 2}, t0);
  pace.finished(Pass::image, 1, t0 + seconds(10));  // the mean: 10 s
  // Frame 2 (a lightning flash, say) has had 12 s and traced only 30 % of its pixels since its
  // first report at 10 %, 2 s in: 10 s for 20 %, so 35 s left, where the mean says none.
  pace.traced(Pass::image, 2, 0.1, t0 + seconds(12));
  pace.traced(Pass::image, 2, 0.3, t0 + seconds(22));
  EXPECT_DOUBLE_EQ(*pace.seconds_left(1, t0 + seconds(22)), 35.0);
}

TEST(RenderPace, AShareBelowTheLastStartsTheRateAgain) {
  const auto t0 = Clock::now();
  RenderPace pace{t0};
  pace.started(Pass::image, {1, 1}, t0);
  pace.traced(Pass::image, 1, 0.9, t0 + seconds(1));  // a stale line from another frame
  pace.traced(Pass::image, 1, 0.05, t0 + seconds(3));
  EXPECT_FALSE(pace.seconds_left(1, t0 + seconds(3)).has_value());
  pace.traced(Pass::image, 1, 0.25, t0 + seconds(5));  // 10 % a second: 7.5 s left
  EXPECT_DOUBLE_EQ(*pace.seconds_left(1, t0 + seconds(5)), 7.5);
}

TEST(ProgressReporter, FollowsThePaceAndLeavesTracedImagesWaitingForDevelopOut) {
  ProgressReporter reporter{nullptr};
  reporter.follow_pace();
  reporter.progress().total = 4;
  reporter.span_started(Pass::image, {1, 2});
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  reporter.picture_traced(Pass::image, 1);
  reporter.report();
  // Frame 1 cost about the time elapsed, and is traced but not yet developed (done 0): 3 left
  // to trace, frame 2 just started and 2 queued, 3 × its cost. Counting frame 1 as still to
  // trace would say 4 ×.
  const auto& p = reporter.progress();
  EXPECT_NEAR(p.eta_seconds / p.elapsed_seconds, 3.0, 0.3);
}

TEST(ProgressReporter, WithoutThePaceUsesTheRateOfFinishedPictures) {
  ProgressReporter reporter{nullptr};
  reporter.progress().total = 4;
  reporter.span_started(Pass::image, {1, 2});
  reporter.picture_traced(Pass::image, 1);
  reporter.report();
  EXPECT_LT(reporter.progress().eta_seconds, 0.0);  // nothing done yet: unknown
  reporter.progress().done = 1;
  reporter.report();
  EXPECT_NEAR(reporter.progress().eta_seconds, reporter.progress().elapsed_seconds * 3, 1e-9);
}

}  // namespace
}  // namespace raintrace::render
