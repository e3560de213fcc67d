// Which frames of an output folder need ray-tracing, and how to cut them into POV-Ray runs.
// Pure apart from checking which images exist, so the resume rules are easy to test.
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "povgen/manifest.h"
#include "render/povray_command.h"

namespace raintrace::render {

/// Frames (ascending) whose image must be (re)made: force, or status not "rendered", or
/// rendered_hash != input_hash, or the image file is missing. Frames outside `only` are left
/// out when it is given.
std::vector<int> frames_needing_render(const povgen::Manifest& manifest,
                                       const std::filesystem::path& out_dir, bool force,
                                       const std::optional<FrameSpan>& only);

/// Cuts ascending frame numbers into contiguous spans. Each POV-Ray start costs ~0.7 s
/// (POVRAY-NOTES), so spans are long, but short enough that `jobs` processes all get work and
/// finish together: about two spans per job, each at most max_span frames, at least 1.
std::vector<FrameSpan> split_into_spans(const std::vector<int>& frames, int jobs, int max_span);

/// Digits of the frame number in the manifest's image names ("images/frame_00001.png" → 5);
/// 4 when there are no frames.
int frame_digits(const povgen::Manifest& manifest);

/// Default number of POV-Ray processes in flight: parsing is single-threaded and tracing uses
/// every core, so one more process than half the cores keeps them busy (2 on 2 cores).
int default_jobs();

}  // namespace raintrace::render
