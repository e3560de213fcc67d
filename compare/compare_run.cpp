// The frame loop: list and match files, then a small pool of threads takes frames by index, so
// results land in name order whatever the scheduling.
#include "compare/compare_run.h"

#include <fmt/core.h>
#include <atomic>
#include <exception>
#include <stdexcept>
#include <thread>

#include "compare/diff_image.h"
#include "compare/frame_matching.h"
#include "compare/image_io.h"

namespace raintrace::compare {

namespace fs = std::filesystem;

bool FrameResult::failed() const {
  return status == FrameStatus::missing_a || status == FrameStatus::missing_b ||
         (status == FrameStatus::compared && metrics.verdict == Verdict::fail);
}

std::string FrameResult::verdict_string() const {
  switch (status) {
    case FrameStatus::compared:
      return to_string(metrics.verdict);
    case FrameStatus::missing_a:
    case FrameStatus::missing_b:
      return "MISSING";
    case FrameStatus::error:
      return "ERROR";
  }
  return "?";
}

bool CompareReport::any_failed() const {
  for (const auto& f : frames) {
    if (f.failed()) return true;
  }
  return false;
}

bool CompareReport::any_error() const {
  for (const auto& f : frames) {
    if (f.status == FrameStatus::error) return true;
  }
  return false;
}

namespace {

std::vector<std::string> image_names(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name[0] == '.' || !entry.is_regular_file()) continue;
    if (is_image_file(entry.path())) names.push_back(name);
  }
  return names;
}

void compare_frame(FrameResult& frame, std::size_t index, const CompareOptions& options) {
  const std::string prefix = fmt::format("{:04}", index + 1);
  try {
    Image a, b;
    if (!frame.a.empty()) a = read_image(frame.a);
    if (!frame.b.empty()) b = read_image(frame.b);
    if (!options.assets_dir.empty()) {
      // The report shows PNGs whatever the input format (a browser cannot show EXR or TIFF).
      if (!frame.a.empty()) {
        frame.asset_reference = prefix + "_reference.png";
        write_image(options.assets_dir / frame.asset_reference, a);
      }
      if (!frame.b.empty()) {
        frame.asset_candidate = prefix + "_candidate.png";
        write_image(options.assets_dir / frame.asset_candidate, b);
      }
    }
    if (frame.status != FrameStatus::compared) return;
    if (a.width != b.width || a.height != b.height || a.channels != b.channels) {
      throw std::runtime_error(fmt::format(
          "images differ in size: '{}' is {} but '{}' is {} (width x height x channels)",
          frame.a.string(), size_string(a), frame.b.string(), size_string(b)));
    }
    frame.metrics = compute_metrics(a, b, options.thresholds);
    if (!options.diff_dir.empty() || !options.assets_dir.empty()) {
      const Image heat = difference_heatmap(a, b);
      if (!options.diff_dir.empty()) {
        frame.diff_image = options.diff_dir / (fs::path(frame.name).stem().string() + "_diff.png");
        write_image(frame.diff_image, heat);
      }
      if (!options.assets_dir.empty()) {
        frame.asset_diff = prefix + "_diff.png";
        write_image(options.assets_dir / frame.asset_diff, heat);
      }
    }
  } catch (const std::exception& e) {
    frame.status = FrameStatus::error;
    frame.error = e.what();
  }
}

}  // namespace

CompareReport compare_paths(const fs::path& a, const fs::path& b, const CompareOptions& options) {
  validate(options.thresholds);
  if (options.threads < 1) {
    throw std::invalid_argument(fmt::format("threads must be >= 1, got {}", options.threads));
  }
  for (const auto& p : {a, b}) {
    if (!fs::exists(p)) throw std::runtime_error(fmt::format("'{}' does not exist", p.string()));
  }
  CompareReport report;
  report.a = a;
  report.b = b;
  report.thresholds = options.thresholds;
  report.folders = fs::is_directory(a);
  if (report.folders != fs::is_directory(b)) {
    throw std::runtime_error(
        fmt::format("cannot compare a folder with a file: '{}' and '{}'", a.string(), b.string()));
  }
  if (report.folders) {
    for (const auto& pair : match_frames(image_names(a), image_names(b))) {
      FrameResult frame;
      frame.name = pair.name;
      if (pair.in_a) frame.a = a / pair.name;
      if (pair.in_b) frame.b = b / pair.name;
      frame.status = !pair.in_a   ? FrameStatus::missing_a
                     : !pair.in_b ? FrameStatus::missing_b
                                  : FrameStatus::compared;
      report.frames.push_back(std::move(frame));
    }
  } else {
    FrameResult frame;
    frame.name = b.filename().string();
    frame.a = a;
    frame.b = b;
    report.frames.push_back(std::move(frame));
  }
  for (const auto& dir : {options.diff_dir, options.assets_dir}) {
    if (!dir.empty()) fs::create_directories(dir);
  }

  const std::size_t n = report.frames.size();
  const int workers = int(std::min<std::size_t>(std::size_t(options.threads), n));
  // One frame at a time may use OIIO's threads; several frames in flight each get one.
  set_oiio_threads(workers > 1 ? 1 : 0);
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t i = next++; i < n; i = next++) compare_frame(report.frames[i], i, options);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < workers; ++t) pool.emplace_back(work);
  work();
  for (auto& thread : pool) thread.join();
  return report;
}

}  // namespace raintrace::compare
