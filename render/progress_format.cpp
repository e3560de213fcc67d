// Progress strings.
#include "render/progress_format.h"

#include <fmt/core.h>
#include <algorithm>
#include <cmath>

namespace raintrace::render {
namespace {

// "30/48 exported" and a separator while frames are exported in the same run, else nothing.
std::string exported_text(const RenderProgress& p, const char* separator) {
  if (p.export_total <= 0) return {};
  return fmt::format("{}/{} exported{}", p.exported, p.export_total, separator);
}

}  // namespace

std::string format_clock(double seconds) {
  const long total = std::lround(std::max(0.0, seconds));
  if (total >= 3600) {
    return fmt::format("{}:{:02d}:{:02d}", total / 3600, (total / 60) % 60, total % 60);
  }
  return fmt::format("{:02d}:{:02d}", total / 60, total % 60);
}

std::string format_progress_bar(const RenderProgress& p, int bar_width) {
  const int finished = p.done + p.failed;
  const double share = p.total > 0 ? static_cast<double>(finished) / p.total : 1.0;
  const int filled = std::clamp(static_cast<int>(std::floor(share * bar_width)), 0, bar_width);
  return fmt::format("[{}{}] {:>4}/{} frames  {}{} failed  {} elapsed  ETA {}",
                     std::string(static_cast<std::size_t>(filled), '#'),
                     std::string(static_cast<std::size_t>(bar_width - filled), '-'), finished,
                     p.total, exported_text(p, "  "), p.failed, format_clock(p.elapsed_seconds),
                     p.eta_seconds < 0 ? std::string{"--:--"} : format_clock(p.eta_seconds));
}

std::string format_progress_line(const RenderProgress& p) {
  return fmt::format(
      "render: {}/{} frames done, {}{} failed, {:.1f} s elapsed, ETA {}", p.done, p.total,
      exported_text(p, ", "), p.failed, p.elapsed_seconds,
      p.eta_seconds < 0 ? std::string{"unknown"} : fmt::format("{:.0f} s", p.eta_seconds));
}

}  // namespace raintrace::render
