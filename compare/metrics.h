// Per-image difference metrics and the pass/warn/fail rule. The threshold semantics are those of
// OpenImageIO's idiff and ImageBufAlgo::compare (OIIO 2.4), so numbers and verdicts can be checked
// against `idiff` on the same files.
#pragma once

#include <cstddef>
#include <limits>
#include <string>

#include "compare/image.h"

namespace raintrace::compare {

/// When a value, a pixel and an image warn or fail. A value is one channel of one pixel; with
/// e = |a − b| and m = (|a| + |b|) / 2 it FAILS when e > fail AND e > fail_relative · m (idiff
/// -fail / -failrelative; a relative threshold of 0 leaves only the absolute test). A pixel
/// fails when any of its channels fails (alpha included). The image FAILS when the number of
/// failing pixels exceeds fail_percent/100 · pixel count, or when the largest value error exceeds
/// hard_fail; otherwise it WARNS by the same rule with the warn fields; otherwise it PASSES.
struct Thresholds {
  /// Absolute per-channel failure threshold, in image units (8-bit 1/255 ≈ 0.0039), >= 0.
  /// Default 1e-6, idiff's default: any visible difference fails.
  double fail = 1e-6;
  /// Absolute per-channel warning threshold, >= 0. Default 1e-6 (idiff's default).
  double warn = 1e-6;
  /// Relative failure threshold (share of the mean magnitude), >= 0. Default 0 (off).
  double fail_relative = 0.0;
  /// Relative warning threshold, >= 0. Default 0 (off).
  double warn_relative = 0.0;
  /// Percentage of pixels allowed to fail, in [0, 100]. Default 0.
  double fail_percent = 0.0;
  /// Percentage of pixels allowed to warn, in [0, 100]. Default 0.
  double warn_percent = 0.0;
  /// Fail if any one value's error exceeds this, >= 0. Default +infinity (off).
  double hard_fail = std::numeric_limits<double>::infinity();
  /// Warn if any one value's error exceeds this, >= 0. Default +infinity (off).
  double hard_warn = std::numeric_limits<double>::infinity();
};

/// Throws std::invalid_argument naming the field when a threshold is negative, NaN or a
/// percentage is outside [0, 100].
void validate(const Thresholds& thresholds);

enum class Verdict { pass, warn, fail };
const char* to_string(Verdict verdict);  ///< "PASS", "WARN", "FAIL"

struct Metrics {
  /// Mean of |a − b| over all values (pixels × channels), as ImageBufAlgo::compare's meanerror;
  /// NaN or +Inf when non-finite values differ (nonfinite_pixels), as idiff reports it.
  double mean_error = 0.0;
  /// Largest |a − b| of any value; +infinity when one side is NaN/Inf and the other is not.
  double max_error = 0.0;
  int max_x = 0;  ///< pixel column of the largest error (first in scan order on ties)
  int max_y = 0;  ///< pixel row of the largest error, 0 = top
  int max_c = 0;  ///< channel index of the largest error
  /// sqrt(mean of (a − b)² over all values), as ImageBufAlgo::compare's rms_error; NaN or
  /// +Inf like mean_error.
  double rmse = 0.0;
  /// 20 · log10(1 / rmse) dB for a peak value of 1 (OIIO's PSNR); +infinity when rmse == 0,
  /// −infinity when it is infinite, NaN when it is NaN.
  double psnr = std::numeric_limits<double>::infinity();
  /// Mean SSIM of the luminance (see ssim.h); 1 for identical images; NaN (undefined) when
  /// non-finite values differ.
  double ssim = 1.0;
  std::size_t pixels = 0;       ///< width × height
  std::size_t warn_pixels = 0;  ///< pixels with at least one warning value
  std::size_t fail_pixels = 0;  ///< pixels with at least one failing value
  double warn_percent = 0.0;    ///< 100 · warn_pixels / pixels
  double fail_percent = 0.0;    ///< 100 · fail_pixels / pixels
  /// Pixels where a NaN or ±Inf on one side meets a different value on the other. Each fails
  /// and warns whatever the thresholds (an infinitely wrong value), and makes mean_error, rmse,
  /// psnr and ssim non-finite: nothing about such an image reads as "close".
  std::size_t nonfinite_pixels = 0;
  /// False when scene-linear values were compared as stored (--linear): PSNR and SSIM assume
  /// display values with a peak of 1, so they are not computed (null in JSON, "-" in tables).
  bool display_metrics = true;
  Verdict verdict = Verdict::pass;
};

/// Compares a (reference) with b (candidate). Both must have the same width, height and channel
/// count, else std::invalid_argument with both sizes. Values that are NaN or ±Inf on both sides
/// in the same way count as equal; a non-finite value against anything else is an infinite
/// error: it fails and warns, and mean, RMSE, PSNR and SSIM report it (nonfinite_pixels).
Metrics compute_metrics(const Image& a, const Image& b, const Thresholds& thresholds = {});

/// The image verdict of `metrics` under `thresholds` (the rule on Thresholds).
Verdict judge(const Metrics& metrics, const Thresholds& thresholds);

/// "160x90x3": how errors name an image's size.
std::string size_string(const Image& image);

}  // namespace raintrace::compare
