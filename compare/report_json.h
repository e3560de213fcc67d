// The machine-readable report: every number of every frame, for CI and scripts.
#pragma once

#include <filesystem>
#include <string>

#include "compare/compare_run.h"

namespace raintrace::compare {

/// JSON text: {"reference", "candidate", "thresholds": {...}, "summary": {"frames", "passed",
/// "warned", "failed", "missing", "errors"}, "frames": [{"name", "reference", "candidate",
/// "result", "mean_error", "max_error", "max_pixel": {"x", "y", "channel"}, "rmse", "psnr",
/// "ssim", "pixels", "warn_pixels", "fail_pixels", "warn_percent", "fail_percent",
/// "diff_image", "error"}]}. Infinite numbers (PSNR of identical images, an unset hard
/// threshold) are written as null, since JSON has no infinity. Metric fields appear only for
/// compared frames.
std::string to_json(const CompareReport& report);

/// Writes to_json(report) to path (through a temporary file and a rename).
void write_json(const std::filesystem::path& path, const CompareReport& report);

}  // namespace raintrace::compare
