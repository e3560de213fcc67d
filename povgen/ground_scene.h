// The wet ground in the output folder: what scene.inc declares for templates/raintrace_ground.inc,
// the puddle mask written once with the shared files, and the names of each frame's ripple map.
#pragma once

#include <filesystem>
#include <string>

#include "povgen/export_params.h"
#include "povgen/ground_maps.h"

namespace raintrace::povgen {

/// Fixed names inside the output folder.
inline constexpr const char* kGroundInclude = "raintrace_ground.inc";
inline constexpr const char* kPuddleMask = "textures/puddle_mask.png";
inline constexpr const char* kRippleFolder = "ripples";

/// True if the scene has puddles: only then does scene.inc include the ground and frames carry
/// ripple maps (without standing water the ground is drawn as the environment has it).
bool ground_applies(const ExportParams& look);

/// scene.inc's lines for the ground (empty unless ground_applies): the camera and ground the
/// masks were made for, then `#include "raintrace_ground.inc"`. Numbers only: nothing from the
/// scene file reaches the text as text.
std::string ground_scene_text(const ExportParams& look);

/// The puddle mask as the camera sees it, for look (ground_applies). Pure.
std::vector<float> ground_puddle_mask(const ExportParams& look);

/// "ripples/ripple_0007.png" for frame 7 (at least 4 digits, as frame files).
std::string ripple_map_name(int frame);

}  // namespace raintrace::povgen
