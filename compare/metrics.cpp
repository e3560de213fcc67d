// Error metrics in one pass over the values, following ImageBufAlgo::compare's definitions so
// the numbers match idiff's; SSIM comes from ssim.cpp.
#include "compare/metrics.h"

#include <fmt/core.h>
#include <cmath>
#include <stdexcept>
#include <string>

#include "compare/ssim.h"

namespace raintrace::compare {

namespace {

void check_non_negative(double value, const char* name) {
  if (!(value >= 0.0)) {
    throw std::invalid_argument(fmt::format("threshold {} must be >= 0, got {}", name, value));
  }
}

void check_percent(double value, const char* name) {
  if (!(value >= 0.0 && value <= 100.0)) {
    throw std::invalid_argument(
        fmt::format("threshold {} must be a percentage in [0, 100], got {}", name, value));
  }
}

// The relative test only applies when a relative threshold is set: with 0 it would compare an
// infinite error against 0 · inf = NaN and let a NaN/Inf mismatch pass.
bool over(double error, double mean_magnitude, double absolute, double relative) {
  return error > absolute && (relative <= 0.0 || error > relative * mean_magnitude);
}

}  // namespace

void validate(const Thresholds& t) {
  check_non_negative(t.fail, "fail");
  check_non_negative(t.warn, "warn");
  check_non_negative(t.fail_relative, "fail-relative");
  check_non_negative(t.warn_relative, "warn-relative");
  check_non_negative(t.hard_fail, "hard-fail");
  check_non_negative(t.hard_warn, "hard-warn");
  check_percent(t.fail_percent, "fail-percent");
  check_percent(t.warn_percent, "warn-percent");
}

const char* to_string(Verdict verdict) {
  switch (verdict) {
    case Verdict::pass:
      return "PASS";
    case Verdict::warn:
      return "WARN";
    case Verdict::fail:
      return "FAIL";
  }
  return "?";
}

std::string size_string(const Image& image) {
  return fmt::format("{}x{}x{}", image.width, image.height, image.channels);
}

Metrics compute_metrics(const Image& a, const Image& b, const Thresholds& t) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels) {
    throw std::invalid_argument(
        fmt::format("images differ in size: {} (width x height x channels) vs {}", size_string(a),
                    size_string(b)));
  }
  Metrics m;
  m.pixels = a.pixel_count();
  const int nc = a.channels;
  double total = 0.0, total_sq = 0.0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      bool warned = false, failed = false, nonfinite = false;
      const float* pa = &a.pixels[(std::size_t(y) * a.width + x) * nc];
      const float* pb = &b.pixels[(std::size_t(y) * a.width + x) * nc];
      for (int c = 0; c < nc; ++c) {
        const double va = pa[c], vb = pb[c];
        double e = std::abs(va - vb);
        if (!std::isfinite(va) || !std::isfinite(vb)) {
          const bool same = (std::isnan(va) && std::isnan(vb)) || (std::isinf(va) && va == vb);
          if (same) continue;
          // Summed as they are (NaN, or Inf against a number: idiff's mean and RMS error then
          // read nan or inf too), but as an error this value is infinitely wrong: it is the
          // largest error, and it fails and warns whatever the thresholds.
          nonfinite = true;
          total += e;
          total_sq += e * e;
          e = std::numeric_limits<double>::infinity();
          warned = failed = true;
        } else {
          total += e;
          total_sq += e * e;
        }
        if (e > m.max_error) {
          m.max_error = e;
          m.max_x = x;
          m.max_y = y;
          m.max_c = c;
        }
        const double magnitude = (std::abs(va) + std::abs(vb)) / 2.0;
        if (!warned && over(e, magnitude, t.warn, t.warn_relative)) warned = true;
        if (!failed && over(e, magnitude, t.fail, t.fail_relative)) failed = true;
      }
      m.warn_pixels += warned;
      m.fail_pixels += failed;
      m.nonfinite_pixels += nonfinite;
    }
  }
  const double values = double(m.pixels) * nc;
  if (values > 0) {
    m.mean_error = total / values;
    m.rmse = std::sqrt(total_sq / values);
  }
  // RMSE 0 → +inf; Inf → −inf; NaN stays NaN.
  m.psnr =
      m.rmse == 0.0 ? std::numeric_limits<double>::infinity() : 20.0 * std::log10(1.0 / m.rmse);
  if (m.pixels > 0) {
    m.warn_percent = 100.0 * double(m.warn_pixels) / double(m.pixels);
    m.fail_percent = 100.0 * double(m.fail_pixels) / double(m.pixels);
  }
  // SSIM would quietly treat the non-finite values as 0: with any of them it is undefined.
  m.ssim = m.nonfinite_pixels > 0 ? std::numeric_limits<double>::quiet_NaN() : ssim(a, b);
  m.verdict = judge(m, t);
  return m;
}

Verdict judge(const Metrics& m, const Thresholds& t) {
  // idiff: "fail if nfail > failpercent/100 · npels || maxerror > hardfail", then the same
  // for warnings.
  const double pixels = m.pixels > 0 ? double(m.pixels) : 1.0;
  if (double(m.fail_pixels) > t.fail_percent / 100.0 * pixels || m.max_error > t.hard_fail) {
    return Verdict::fail;
  }
  if (double(m.warn_pixels) > t.warn_percent / 100.0 * pixels || m.max_error > t.hard_warn) {
    return Verdict::warn;
  }
  return Verdict::pass;
}

}  // namespace raintrace::compare
