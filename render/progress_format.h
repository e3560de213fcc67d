// Progress text for `raintrace render`: a self-updating bar for terminals and plain lines for
// logs. Only the text lives here (testable); cli/ decides where and when it is printed.
#pragma once

#include <string>

#include "render/progress.h"

namespace raintrace::render {

/// "[##########----------]  12/48 frames  1 failed  00:12 elapsed  ETA 00:36", bar_width
/// characters of bar; "ETA --:--" while unknown. While the same run exports frames,
/// "30/48 exported" follows the frame count.
std::string format_progress_bar(const RenderProgress& progress, int bar_width = 30);

/// "render: 12/48 frames done, 1 failed, 12.3 s elapsed, ETA 36 s"; while the same run
/// exports frames "render: 12/48 frames done, 30/48 exported, 1 failed, …".
std::string format_progress_line(const RenderProgress& progress);

/// Seconds as "MM:SS", or "H:MM:SS" from one hour on.
std::string format_clock(double seconds);

}  // namespace raintrace::render
