// What scene.inc says about the rain's light, beyond the frame files' geometry: the drop's
// scattering lobes that templates/raintrace_materials.inc gives every streak, and the rain
// medium that continues the streaks beyond far_m (docs/rain-appearance.md). Pure text.
#pragma once

#include <string>

#include "povgen/export_params.h"

namespace raintrace::povgen {

/// Outer radius of the rain medium around the camera, metres. The environments' scenery lies
/// within it; the sky beyond already shows the sky through the rest of the rain.
inline constexpr double kRainMediumRadiusM = 200.0;

/// `#declare RT_DropBrilliance`, `RT_DropLobeFront` and `RT_DropLobeBack`: the POV-Ray finish
/// that stands in for a water drop's scattering (sim::fit_povray_lobes of the geometric optics
/// of a drop), for raintrace_materials.inc.
std::string drop_lobes_text();

/// The rain beyond look.rain.far_m, declared as two macros for scene.inc to call (empty text
/// when the rain rate is 0 or look.rain_medium is false):
/// - RT_RainMedium(): POV-Ray media in a hollow container from the plane at depth far_m to
///   kRainMediumRadiusM around the camera, with the δ-scaled extinction of the configured rain
///   (sim::rain_medium_optics), all of it scattering with a Henyey-Greenstein phase function,
///   and emission = extinction × RT_RainSurround for the light of the surroundings the drops
///   refract (the lights are scattered by POV-Ray itself). Scattering is written as
///   extinction/4 with `extinction 4`: POV-Ray adds Sc·P(θ)·C per metre for a light of colour
///   C, and C stands for E/π (a white diffuse patch facing it shows C), while physics adds
///   σ·E·P/4π = σ/4·C·P.
/// - RT_RainFog(): the same extinction and emission as a POV-Ray fog whose transmit caps it at
///   kRainMediumRadiusM: free, but without the lights' scattering (the preview without a plate).
std::string rain_medium_text(const ExportParams& look);

}  // namespace raintrace::povgen
