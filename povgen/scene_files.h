// Part (b) for the files shared by all frames: scene.inc (camera, lights, fog, environment and
// materials includes), scene.pov (the frame dispatcher), scene.ini (the animation for plain
// `povray scene.ini`), and their rain-mask twins. Pure text; nothing here touches the disk.
#pragma once

#include <string>

#include "povgen/export_params.h"

namespace raintrace::povgen {

/// Fixed names inside the output folder. User text never chooses a name.
inline constexpr const char* kEnvironmentInclude = "environment.inc";
inline constexpr const char* kMaterialsInclude = "raintrace_materials.inc";
inline constexpr const char* kStreakAtlas = "textures/streak_atlas.png";
/// Scene-linear HDR like the frames: lamps far above 1 and the dark end pass through unchanged.
inline constexpr const char* kEnvironmentPlate = "textures/environment_plate.exr";
inline constexpr const char* kSceneInclude = "scene.inc";
inline constexpr const char* kPlateIni = "plate.ini";
inline constexpr const char* kPlatePov = "plate.pov";

/// scene.inc for these params. Checks the params POV-Ray text depends on (finite numbers,
/// image size in [16, 8192], a built-in environment name unless an include is used) and throws
/// std::invalid_argument naming the field otherwise.
std::string scene_inc_text(const ExportParams& look);

/// Whether frames may draw the environment plate: quality preview, look.environment_plate,
/// a built-in environment whose scenery all lies beyond the rain (night_street, field; not
/// closeup, whose backdrop wall stands inside it), no lens barrel (optical_vignetting: the
/// plate went through it already) and no fog thicker than kPlateFogDimming across the rain
/// within rain.far_m. The plate holds the fog, so frames that draw it leave the fog out, and a
/// drop there misses the fog in front of it: at most 1 − e^(−density·rain.far_m) of its light.
/// The rain drawn around a lamp farther off (rain.lamp_reach_m) misses more, but its faint
/// streaks carry little of the light in the lamp's glow (BENCHMARKS.md: in the cone of the
/// default's lamp 22 m off, where they miss ~15 %, the frame changes by 0.07 %).
bool environment_plate_applies(const ExportParams& look);

/// The most a drop within rain.far_m may miss of the fog in front of it where frames draw the
/// plate: the default example's mist (0.0075 /m over its far_m of 6 m) dims the farthest by 4.4 %.
inline constexpr double kPlateFogDimming = 0.05;

/// plate.pov: the environment alone (scene.inc with RT_NoPlate=1, no rain).
std::string plate_pov_text();

/// plate.ini: renders plate.pov into textures/environment_plate.exr at the frames' size.
std::string plate_ini_text(const ExportParams& look);

/// scene.pov: includes frames/<prefix>_NNNN.pov for POV-Ray's frame_number (prefix "frame"
/// or "mask"; digits from frame_digits()).
std::string dispatcher_text(const char* prefix, int digits);

/// Frames first..last (1-based, inclusive) of an animation.
struct FrameSubset {
  int first = 1;
  int last = 1;
};

/// scene.ini (prefix "frame", dispatcher "scene.pov") or mask.ini ("mask", "mask.pov"):
/// renders frames `frames` of a frame_count-frame animation from inside the folder into
/// images/frame_NNNN.exr (half-float OpenEXR, scene-linear: raintrace develops each into
/// images/frame_NNNN.png) or images/mask_NNNN.png. Throws std::invalid_argument unless
/// 1 <= first <= last <= frame_count.
std::string ini_text(const ExportParams& look, int frame_count, const char* prefix,
                     const char* dispatcher, FrameSubset frames);

}  // namespace raintrace::povgen
