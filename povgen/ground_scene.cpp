// The wet ground's part of the output folder (see ground_scene.h).
#include "povgen/ground_scene.h"

#include "povgen/frame_text.h"
#include "povgen/number_format.h"
#include "sim/puddles.h"
#include "sim/ripples.h"

namespace raintrace::povgen {

bool ground_applies(const ExportParams& look) { return look.ground.puddles.coverage > 0.0; }

std::string ground_scene_text(const ExportParams& look) {
  if (!ground_applies(look)) return {};
  const sim::Camera& c = look.camera;
  std::string text;
  text += "#declare RT_GroundLookAt=" + format_vector(c.look_at) + ";\n";
  text += "#declare RT_GroundAngle=" + format_number(c.fov_deg) + ";\n";
  text += "#declare RT_GroundWidth=" + std::to_string(look.width) + ";\n";
  text += "#declare RT_GroundHeight=" + std::to_string(look.height) + ";\n";
  text += "#declare RT_GroundY=" + format_number(look.ground.ground_y_m) + ";\n";
  text += "#declare RT_PuddleMask=\"" + std::string{kPuddleMask} + "\";\n";
  text += "#declare RT_PuddleFringe=" + format_number(sim::PuddleField::kFringeM) + ";\n";
  text += "#declare RT_RippleHeightRange=" + format_number(kRippleHeightRange) + ";\n";
  const double roughness =
      look.ground.ripples.enabled
          ? sim::ripple_slope_rms(look.rain.rate_mm_per_h, look.ground.ripples.lifetime_s)
          : 0.0;
  text += "#declare RT_RippleRoughness=" + format_number(roughness) + ";\n";
  text += "#declare RT_RippleWavelength=" + format_number(sim::ripple_wavelength()) + ";\n";
  text += "#declare RT_RippleSpeed=" + format_number(sim::ripple_speed()) + ";\n";
  // The mask is made from these; written here, a change of them changes scene.inc (and so
  // every input hash that covers it, the plate's too).
  const sim::PuddleParams& p = look.ground.puddles;
  text += "// puddles: coverage " + format_number(p.coverage) + ", size_m " +
          format_number(p.size_m) + ", depth_mm " + format_number(p.depth_mm) + ", film_mm " +
          format_number(p.film_mm) + ", seed " + std::to_string(p.seed) + "\n";
  text += "#include \"" + std::string{kGroundInclude} + "\"\n";
  return text;
}

std::vector<float> ground_puddle_mask(const ExportParams& look) {
  const GroundPixels pixels(look.camera, look.width, look.height, look.ground.ground_y_m);
  return puddle_mask(pixels, sim::PuddleField(look.ground.puddles, look.ground.puddles.seed));
}

std::string ripple_map_name(int frame) {
  return std::string{kRippleFolder} + "/" + frame_file_name("ripple", frame, 4, ".png");
}

}  // namespace raintrace::povgen
