// Exposure and input cleaning (contract in exposure.h).
#include "film/exposure.h"

#include <cmath>
#include <stdexcept>

namespace raintrace::film {

void apply_exposure(RgbImage& image, double exposure_ev) {
  if (!(std::fabs(exposure_ev) <= kExposureLimitEv)) {
    throw std::invalid_argument("exposure must be in [-16, 16] stops");
  }
  const auto gain = float(std::exp2(exposure_ev));
  for (float& v : image.pixels) {
    // `v > 0` is false for NaN, so NaN lands on 0 with the negatives.
    v = (v > 0.0f ? std::fmin(v, kHalfMax) : 0.0f) * gain;
  }
}

}  // namespace raintrace::film
