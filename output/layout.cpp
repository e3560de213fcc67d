// File names of the output folder.
#include "output/layout.h"

#include <fmt/core.h>

namespace raintrace::output {

const char* pass_prefix(Pass pass) { return pass == Pass::image ? "frame" : "mask"; }

std::string final_image_name(Pass pass, int frame, int digits) {
  // EXR: the frame is scene-linear light for develop and compositors; a mask is data.
  return fmt::format("{}/{}_{:0{}d}.{}", kImagesDir, pass_prefix(pass), frame, digits,
                     pass == Pass::image ? "exr" : "png");
}

std::string developed_image_name(int frame, int digits) {
  return fmt::format("{}/{}_{:0{}d}.png", kImagesDir, pass_prefix(Pass::image), frame, digits);
}

std::string frame_scene_name(Pass pass, int frame, int digits) {
  return fmt::format("{}/{}_{:0{}d}.pov", kFramesDir, pass_prefix(pass), frame, digits);
}

}  // namespace raintrace::output
