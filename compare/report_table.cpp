// Fixed-width table formatting with fmt.
#include "compare/report_table.h"

#include <fmt/core.h>
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace raintrace::compare {

namespace {

std::string psnr_text(double psnr) {
  if (std::isinf(psnr)) return psnr > 0 ? "inf" : "-inf";
  return fmt::format("{:.2f}", psnr);
}

}  // namespace

std::string format_table(const CompareReport& report) {
  std::size_t name_width = 5;
  for (const auto& f : report.frames) name_width = std::max(name_width, f.name.size());
  std::string out =
      fmt::format("{:<{}}  {:>10} {:>10} {:>10} {:>8} {:>8} {:>8} {:>8}  {}\n", "frame", name_width,
                  "mean", "max", "RMSE", "PSNR", "SSIM", "%>warn", "%>fail", "result");
  std::map<std::string, int> counts;
  for (const auto& f : report.frames) {
    const std::string verdict = f.verdict_string();
    ++counts[verdict];
    if (f.status == FrameStatus::compared) {
      const Metrics& m = f.metrics;
      out +=
          fmt::format("{:<{}}  {:>10.4g} {:>10.4g} {:>10.4g} {:>8} {:>8} {:>8.3f} {:>8.3f}  {}\n",
                      f.name, name_width, m.mean_error, m.max_error, m.rmse,
                      m.display_metrics ? psnr_text(m.psnr) : "-",
                      m.display_metrics ? fmt::format("{:.4f}", m.ssim) : "-", m.warn_percent,
                      m.fail_percent, verdict);
    } else {
      const std::string why = f.status == FrameStatus::missing_a   ? "only in " + report.b.string()
                              : f.status == FrameStatus::missing_b ? "only in " + report.a.string()
                                                                   : f.error;
      out += fmt::format("{:<{}}  {}  ({})\n", f.name, name_width, verdict, why);
    }
  }
  for (const auto& f : report.frames) {
    if (f.status == FrameStatus::compared && f.metrics.nonfinite_pixels > 0) {
      out += fmt::format("{}: {} pixel(s) hold NaN or Inf where the other image does not\n", f.name,
                         f.metrics.nonfinite_pixels);
    }
  }
  // How HDR input was developed, once per distinct way (usually one line for the whole run).
  std::vector<std::string> ways;
  for (const auto& f : report.frames) {
    for (const std::string* how : {&f.developed_a, &f.developed_b}) {
      if (!how->empty() && std::find(ways.begin(), ways.end(), *how) == ways.end()) {
        ways.push_back(*how);
      }
    }
  }
  if (ways.size() == 1) {
    out += fmt::format("HDR input developed for comparison: {}\n", ways.front());
  } else if (ways.size() > 1) {
    out += fmt::format("HDR input developed for comparison {} ways (--json names each)\n",
                       ways.size());
  }
  const Thresholds& t = report.thresholds;
  out += fmt::format("{} frame(s): ", report.frames.size());
  bool first = true;
  for (const char* v : {"PASS", "WARN", "FAIL", "MISSING", "ERROR"}) {
    if (!counts.count(v)) continue;
    out += fmt::format("{}{} {}", first ? "" : ", ", counts[v], v);
    first = false;
  }
  out += fmt::format("  (fail > {:g} on > {:g}% of pixels, warn > {:g} on > {:g}%", t.fail,
                     t.fail_percent, t.warn, t.warn_percent);
  if (std::isfinite(t.hard_fail)) out += fmt::format(", hard fail > {:g}", t.hard_fail);
  out += ")\n";
  return out;
}

}  // namespace raintrace::compare
