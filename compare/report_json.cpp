// JSON report via nlohmann::json.
#include "compare/report_json.h"

#include <fmt/core.h>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace raintrace::compare {

namespace {

nlohmann::json number(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

}  // namespace

std::string to_json(const CompareReport& report) {
  using nlohmann::json;
  const Thresholds& t = report.thresholds;
  json doc;
  doc["reference"] = report.a.string();
  doc["candidate"] = report.b.string();
  doc["thresholds"] = {{"fail", t.fail},
                       {"warn", t.warn},
                       {"fail_relative", t.fail_relative},
                       {"warn_relative", t.warn_relative},
                       {"fail_percent", t.fail_percent},
                       {"warn_percent", t.warn_percent},
                       {"hard_fail", number(t.hard_fail)},
                       {"hard_warn", number(t.hard_warn)}};
  int passed = 0, warned = 0, failed = 0, missing = 0, errors = 0;
  json frames = json::array();
  for (const auto& f : report.frames) {
    json frame;
    frame["name"] = f.name;
    frame["reference"] = f.a.empty() ? json(nullptr) : json(f.a.string());
    frame["candidate"] = f.b.empty() ? json(nullptr) : json(f.b.string());
    frame["result"] = f.verdict_string();
    // How an HDR side was developed before comparing; null: compared as stored.
    frame["reference_developed"] = f.developed_a.empty() ? json(nullptr) : json(f.developed_a);
    frame["candidate_developed"] = f.developed_b.empty() ? json(nullptr) : json(f.developed_b);
    if (f.status == FrameStatus::compared) {
      const Metrics& m = f.metrics;
      frame["mean_error"] = number(m.mean_error);
      frame["max_error"] = number(m.max_error);
      frame["max_pixel"] = {{"x", m.max_x}, {"y", m.max_y}, {"channel", m.max_c}};
      frame["rmse"] = number(m.rmse);
      // Not computed for scene-linear values compared as stored (--linear): null.
      frame["psnr"] = m.display_metrics ? number(m.psnr) : json(nullptr);
      frame["ssim"] = m.display_metrics ? number(m.ssim) : json(nullptr);
      frame["pixels"] = m.pixels;
      frame["warn_pixels"] = m.warn_pixels;
      frame["fail_pixels"] = m.fail_pixels;
      frame["warn_percent"] = m.warn_percent;
      frame["fail_percent"] = m.fail_percent;
      // Why mean_error, rmse, psnr and ssim may be null: NaN or Inf meeting other values.
      frame["nonfinite_pixels"] = m.nonfinite_pixels;
      passed += m.verdict == Verdict::pass;
      warned += m.verdict == Verdict::warn;
      failed += m.verdict == Verdict::fail;
    } else if (f.status == FrameStatus::error) {
      frame["error"] = f.error;
      ++errors;
    } else {
      ++missing;
    }
    if (!f.diff_image.empty()) frame["diff_image"] = f.diff_image.string();
    frames.push_back(std::move(frame));
  }
  doc["summary"] = {{"frames", report.frames.size()},
                    {"passed", passed},
                    {"warned", warned},
                    {"failed", failed},
                    {"missing", missing},
                    {"errors", errors}};
  doc["frames"] = std::move(frames);
  return doc.dump(2) + "\n";
}

void write_json(const std::filesystem::path& path, const CompareReport& report) {
  const std::string text = to_json(report);
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error(fmt::format("cannot write '{}'", tmp.string()));
  }
  std::filesystem::rename(tmp, path);
}

}  // namespace raintrace::compare
