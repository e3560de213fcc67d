// Rain as a medium beyond far_m (see rain_medium.h).
#include "sim/rain_medium.h"

#include "sim/drop_optics.h"
#include "sim/drop_size.h"

namespace raintrace::sim {

RainMediumOptics rain_medium_optics(const RainParams& rain) {
  const DropSizeModel sizes(rain);
  RainMediumOptics optics;
  optics.image_extinction_per_m = sizes.cross_section_per_m();
  optics.extinction_per_m = 2.0 * optics.image_extinction_per_m;
  // Geometric optics does not depend on the drop's size: one trace serves every scene.
  optics.eccentricity = water_drop_scattering().asymmetry;
  return optics;
}

}  // namespace raintrace::sim
