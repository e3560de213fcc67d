// scene.inc's rain optics (see rain_look.h).
#include "povgen/rain_look.h"

#include <glm/geometric.hpp>

#include "povgen/number_format.h"
#include "sim/drop_optics.h"
#include "sim/rain_medium.h"

namespace raintrace::povgen {
std::string drop_lobes_text() {
  const sim::PovrayLobes lobes = sim::fit_povray_lobes(sim::water_drop_scattering());
  return "#declare RT_DropBrilliance=" + format_number(lobes.brilliance) +
         ";\n#declare RT_DropLobeFront=" + format_number(lobes.front) +
         ";\n#declare RT_DropLobeBack=" + format_number(lobes.back) + ";\n";
}

std::string rain_medium_text(const ExportParams& look) {
  if (!look.rain_medium || !(look.rain.rate_mm_per_h > 0.0)) return {};
  const sim::RainMediumOptics optics = sim::rain_medium_optics(look.rain);
  const double sigma = optics.image_extinction_per_m;
  if (!(sigma > 0.0)) return {};
  const glm::dvec3 eye = look.camera.position;
  const glm::dvec3 forward = glm::normalize(look.camera.look_at - eye);
  // The half-space beyond depth far_m, where no drop is simulated: plane{normal, offset} keeps
  // normal·p <= offset inside, so its normal points back to the camera.
  const double offset = -(glm::dot(forward, eye) + look.rain.far_m);
  std::string text;
  text += "// The rain beyond far_m as a medium (sim/rain_medium.h): extinction " +
          format_number(sigma) + " /m.\n";
  text += "#declare RT_RainExtinction=" + format_number(sigma) + ";\n";
  text += "#macro RT_RainMedium()\n";
  text += "intersection{\n sphere{" + format_vector(eye) + "," + format_number(kRainMediumRadiusM) +
          "}\n plane{" + format_vector(-forward) + "," + format_number(offset) + "}\n";
  // No diffuse, no ambient: POV-Ray then skips the container surface's light loop.
  text += " hollow texture{pigment{rgbt 1} finish{ambient 0 diffuse 0}}\n";
  // The medium is smooth and thin (τ ≈ 0.07 over 200 m at 5 mm/h): one sample per ray at the
  // middle of its path through it. Method 2 with one sample differs from method 3 (which takes
  // 5) by < 0.002 in radiance next to a lamp, at 40 % of its cost. No jitter: repeatable.
  text += " interior{media{method 2 intervals 1 samples 1,1 jitter 0\n";
  text += "  scattering{5,RT_RainExtinction/4 eccentricity " + format_number(optics.eccentricity) +
          " extinction 4}\n";
  text += "  emission RT_RainExtinction*RT_RainSurround}}\n no_shadow\n}\n#end\n";
  // The same slab as POV-Ray fog: fog's colour is what the slab adds, its transmit the least
  // it lets through (POV-Ray clamps a fog's transmittance to at least its transmit), so rays to
  // the sky see exactly the 200 m of rain. It starts at the camera instead of far_m (the rain
  // inside far_m is then counted twice, σ·far_m ≈ 0.2 % at 5 mm/h) and scatters no light
  // source; it costs nothing.
  text += "#macro RT_RainFog()\n";
  text += "fog{fog_type 1 distance 1/RT_RainExtinction color rgb RT_RainSurround transmit exp(-" +
          format_number(kRainMediumRadiusM) + "*RT_RainExtinction)}\n#end\n";
  return text;
}

}  // namespace raintrace::povgen
