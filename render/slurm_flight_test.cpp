// The Slurm tasks' flight files and the submitter's following of them (slurm_flight.h), without
// a cluster: the files are written here as a task writes them. The Slurm suite (slurm_render_test)
// runs them through real array tasks.
#include "render/slurm_flight.h"

#include <gtest/gtest.h>
#include <chrono>
#include <fstream>
#include <thread>

#include "render/test_folder.h"

namespace raintrace::render {
namespace {

// A reporter following the pace of a run of `total` pictures, recording its last ETA.
struct EtaProbe {
  double eta = -1.0;
  ProgressReporter reporter{[this](const RenderProgress& p) { eta = p.eta_seconds; }};
  explicit EtaProbe(int total) {
    reporter.progress().total = total;
    reporter.follow_pace();
  }
  double eta_now() {
    reporter.report();
    return eta;
  }
};

// Task 0's flight over frames 1–3, written for `written_for` at `first_share`, then 30 ms later at
// `second_share`, each time followed for `followed`.
void report_twice(const std::filesystem::path& results, const std::string& written_for,
                  const std::string& followed, EtaProbe& probe, int frame, double first_share,
                  double second_share) {
  FlightFollower flights;
  publish_flight(results, 0, written_for, {Pass::image, {1, 3}, frame, first_share});
  flights.follow(results, followed, probe.reporter);
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  publish_flight(results, 0, written_for, {Pass::image, {1, 3}, frame, second_share});
  flights.follow(results, followed, probe.reporter);
}

TEST(FlightFollower, ATasksTracedShareGivesAnEtaBeforeAnyFrameIsDone) {
  const auto results = testing::fresh_test_dir("flight_eta");
  EtaProbe probe{3};
  report_twice(results, "run-1", "run-1", probe, 1, 0.05, 0.35);
  // The frame traced 0.3 of itself in the time between: it has about 0.65/0.3 of that left,
  // and the two queued frames cost it whole each, so the ETA is about 8.5 times that time.
  const double eta = probe.eta_now();
  EXPECT_GT(eta, 0.0);
  EXPECT_LT(eta, 60.0);
}

TEST(FlightFollower, FlightsOfAnotherRunAndUnreadableFilesAreIgnored) {
  const auto results = testing::fresh_test_dir("flight_other_run");
  EtaProbe probe{3};
  std::ofstream{results / ".flight_1.json"} << "{\"run_id\": \"run-1\", \"task\":";  // cut short
  report_twice(results, "run-0", "run-1", probe, 1, 0.05, 0.35);
  EXPECT_LT(probe.eta_now(), 0.0);
}

TEST(FlightFollower, ATaskFirstSeenPastItsFirstFrameIsFollowedFromThere) {
  // A task that finished frames 1 and 2 before the first poll: the follower starts it at frame
  // 3, so once frame 3 is traced nothing is left in flight and no ETA is owed for 1 or 2.
  const auto results = testing::fresh_test_dir("flight_late");
  EtaProbe probe{1};
  report_twice(results, "run-1", "run-1", probe, 3, 0.1, 0.6);
  EXPECT_GT(probe.eta_now(), 0.0);
  probe.reporter.picture_traced(Pass::image, 3);
  // Traced, not yet developed: nothing is left to trace.
  EXPECT_EQ(probe.eta_now(), 0.0);
}

TEST(FlightFollower, ARetiredTaskLeavesNoFile) {
  const auto results = testing::fresh_test_dir("flight_retired");
  publish_flight(results, 2, "run-1", {Pass::mask, {4, 4}, 4, -1.0});
  EXPECT_TRUE(std::filesystem::exists(results / ".flight_2.json"));
  retire_flight(results, 2);
  EXPECT_FALSE(std::filesystem::exists(results / ".flight_2.json"));
  retire_flight(results, 2);  // twice is harmless
}

}  // namespace
}  // namespace raintrace::render
