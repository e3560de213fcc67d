// Checks of ExportParams against its tables (export_params.h) before any value reaches POV-Ray
// text: the scene reader already checked the same rows, this is the second line of defence.
#include "povgen/export_params.h"

#include <cmath>
#include <stdexcept>

#include "povgen/templates.h"

namespace raintrace::povgen {

void check_optical_vignetting(const ExportParams& look) {
  if (look.optical_vignetting > 0.0 && !traces_focal_blur(look)) {
    throw std::invalid_argument(
        "camera: optical_vignetting needs a traced focal blur (aperture_m > 0, focal_blur = "
        "\"traced\")");
  }
}

void validate(const ExportParams& look) {
  sim::validate(look.camera);
  sim::check_params<ExportParams>(kExportParams, look);
  sim::check_params<FogParams>(kFogParams, look.fog);
  // The rain's rate and sizes reach scene.inc (the rain medium, the ripples' roughness) and
  // the ground's numbers scene.inc and the masks: the simulation's own ranges.
  sim::check_params<sim::RainParams>(sim::kRainParams, look.rain);
  sim::check_params<sim::PuddleParams>(sim::kPuddleParams, look.ground.puddles);
  sim::check_params<sim::RippleParams>(sim::kRippleParams, look.ground.ripples);
  check_optical_vignetting(look);
  if (!std::isfinite(look.ground.ground_y_m)) {
    throw std::invalid_argument("ground: ground_y_m must be finite");
  }
  // The name goes into no text, but an unknown one would silently pick no environment.
  if (look.environment.include_path.empty()) environment_template(look.environment.name);
}

}  // namespace raintrace::povgen
