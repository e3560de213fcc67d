// Names inside an output folder. raintrace chooses every one of them (user text never does), and
// each is written here once: the exporter, the renderers and the tests all take them from here.
#pragma once

#include <string>

namespace raintrace::output {

inline constexpr const char* kManifest = "manifest.json";
/// Held (an OS lock) by the run that uses the folder; says who that is while it is held.
inline constexpr const char* kLockFile = "raintrace.lock";
inline constexpr const char* kMovie = "animation.mp4";
inline constexpr const char* kGif = "animation.gif";
inline constexpr const char* kContactSheet = "contact_sheet.png";
inline constexpr const char* kImagesDir = "images";
inline constexpr const char* kFramesDir = "frames";
inline constexpr const char* kLogsDir = "logs";

/// A contiguous run of frames, 1-based, inclusive.
struct FrameSpan {
  int first = 1;
  int last = 1;
  [[nodiscard]] int count() const { return last - first + 1; }
  [[nodiscard]] bool contains(int frame) const { return frame >= first && frame <= last; }
};

/// The two pictures POV-Ray renders for a frame.
enum class Pass {
  image,  ///< scene.ini → images/frame_NNNN.exr (scene-linear HDR, developed into a PNG)
  mask,   ///< mask.ini (the rain alone, white on black) → images/mask_NNNN.png
};

/// "frame" or "mask": the word in the pass's file names.
const char* pass_prefix(Pass pass);

/// Where the picture POV-Ray rendered for a frame lives, relative to the output folder:
/// "images/frame_0007.exr" or "images/mask_0007.png"; `digits` as in the frame file names (4,
/// more past 9999 frames: povgen::frame_digits).
std::string final_image_name(Pass pass, int frame, int digits = 4);

/// Where a frame's developed picture lives (its EXR through film/): "images/frame_0007.png".
std::string developed_image_name(int frame, int digits = 4);

/// The frame's POV-Ray file, relative to the output folder: "frames/frame_0007.pov" or
/// "frames/mask_0007.pov".
std::string frame_scene_name(Pass pass, int frame, int digits = 4);

}  // namespace raintrace::output
