// The terminal table: one aligned row per frame, so a folder of frames reads at a glance.
#pragma once

#include <string>

#include "compare/compare_run.h"

namespace raintrace::compare {

/// Columns: frame, mean, max, RMSE, PSNR (dB, "inf" when identical), SSIM, % over warn,
/// % over fail, verdict; a header line, one row per frame (MISSING/ERROR rows say why in place
/// of the numbers), then a summary line with the thresholds and the counts per verdict. Every
/// line ends in '\n'.
std::string format_table(const CompareReport& report);

}  // namespace raintrace::compare
