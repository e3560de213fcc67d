// What each Slurm array task has in flight (slurm_flight.h).
#include "render/slurm_flight.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>
#include <system_error>

#include "povgen/output_folder.h"
#include "render/text_file.h"

namespace raintrace::render {
namespace {

using nlohmann::json;

constexpr const char* kFlightPrefix = ".flight_";

std::filesystem::path flight_path(const std::filesystem::path& results, int task) {
  return results / fmt::format("{}{}.json", kFlightPrefix, task);
}

}  // namespace

void publish_flight(const std::filesystem::path& results, int task, const std::string& run_id,
                    const TaskFlight& flight) {
  povgen::write_file_atomic(flight_path(results, task),
                            json{{"run_id", run_id},
                                 {"task", task},
                                 {"pass", output::pass_prefix(flight.pass)},
                                 {"first", flight.span.first},
                                 {"last", flight.span.last},
                                 {"frame", flight.frame},
                                 {"share", flight.share}}
                                .dump());
}

void retire_flight(const std::filesystem::path& results, int task) {
  std::error_code ignored;
  std::filesystem::remove(flight_path(results, task), ignored);
}

void FlightFollower::follow(const std::filesystem::path& results, const std::string& run_id,
                            ProgressReporter& reporter) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(results, ec)) {
    const auto name = entry.path().filename().string();
    if (name.rfind(kFlightPrefix, 0) != 0 || entry.path().extension() != ".json") continue;
    TaskFlight flight;
    int task = 0;
    try {
      const json j = json::parse(read_text(entry.path()));
      if (j.at("run_id").get<std::string>() != run_id) continue;
      task = j.at("task").get<int>();
      flight.pass = j.at("pass").get<std::string>() == output::pass_prefix(Pass::mask)
                        ? Pass::mask
                        : Pass::image;
      flight.span = {j.at("first").get<int>(), j.at("last").get<int>()};
      flight.frame = j.at("frame").get<int>();
      flight.share = j.at("share").get<double>();
    } catch (const json::exception&) {
      continue;  // gone or replaced while read: the next poll reads it again
    }
    const auto seen = m_seen.find(task);
    const bool new_process = seen == m_seen.end() || seen->second.pass != flight.pass ||
                             seen->second.span.first != flight.span.first ||
                             seen->second.span.last != flight.span.last;
    if (new_process) reporter.span_started(flight.pass, {flight.frame, flight.span.last});
    m_seen[task] = flight;
    if (flight.share >= 0.0) reporter.picture_share(flight.pass, flight.frame, flight.share);
  }
}

}  // namespace raintrace::render
