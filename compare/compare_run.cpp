// The frame loop: list and match files, then a small pool of threads takes frames by index, so
// results land in name order whatever the scheduling.
#include "compare/compare_run.h"

#include <fmt/core.h>
#include <algorithm>
#include <atomic>
#include <cctype>
#include <exception>
#include <map>
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

bool is_hdr_file(const fs::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".exr" || ext == ".hdr";
}

// The folder's image files by name without extension: one each, the HDR file or the picture
// where both exist (a render folder holds frame_0001.exr beside frame_0001.png).
std::map<std::string, std::string> image_names(const fs::path& dir, bool prefer_hdr) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name[0] == '.' || !entry.is_regular_file()) continue;
    if (is_image_file(entry.path())) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  std::map<std::string, std::string> by_stem;
  for (const std::string& name : names) {
    const std::string stem = fs::path{name}.stem().string();
    const auto [it, inserted] = by_stem.emplace(stem, name);
    // The first name wins, unless this one is of the preferred kind and the first is not.
    if (!inserted && is_hdr_file(name) == prefer_hdr && is_hdr_file(it->second) != prefer_hdr) {
      it->second = name;
    }
  }
  return by_stem;
}

std::vector<std::string> keys_of(const std::map<std::string, std::string>& m) {
  std::vector<std::string> keys;
  for (const auto& [key, value] : m) keys.push_back(key);
  return keys;
}

void compare_frame(FrameResult& frame, std::size_t index, const CompareOptions& options,
                   HdrInput& hdr) {
  const std::string prefix = fmt::format("{:04}", index + 1);
  try {
    Image a, b;
    if (!frame.a.empty()) a = read_image(frame.a);
    if (!frame.b.empty()) b = read_image(frame.b);
    // Developed against the other side as it was read (its description), then compared.
    const Image read_a = a;
    frame.developed_a = hdr.prepare(a, frame.b.empty() ? nullptr : &b);
    frame.developed_b = hdr.prepare(b, frame.a.empty() ? nullptr : &read_a);
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
    if (a.scene_linear && b.scene_linear) {
      // --linear: PSNR and SSIM assume display values with a peak of 1.
      frame.metrics.display_metrics = false;
    }
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
    const auto names_a = image_names(a, options.prefer_hdr);
    const auto names_b = image_names(b, options.prefer_hdr);
    for (const auto& pair : match_frames(keys_of(names_a), keys_of(names_b))) {
      FrameResult frame;
      frame.name = pair.in_b ? names_b.at(pair.name) : names_a.at(pair.name);
      if (pair.in_a) frame.a = a / names_a.at(pair.name);
      if (pair.in_b) frame.b = b / names_b.at(pair.name);
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
  HdrInput hdr{options.hdr};
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t i = next++; i < n; i = next++) {
      compare_frame(report.frames[i], i, options, hdr);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < workers; ++t) pool.emplace_back(work);
  work();
  for (auto& thread : pool) thread.join();
  return report;
}

}  // namespace raintrace::compare
