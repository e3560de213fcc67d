// Exposure in stops, applied to the scene-linear frame before anything else, and the one place
// that makes a rendered HDR frame safe to develop.
#pragma once

#include "film/rgb_image.h"

namespace raintrace::film {

/// Exposures from −16 to +16 stops are accepted: 2^±16 spans any sensible scene.
inline constexpr double kExposureLimitEv = 16.0;

/// Largest finite half float: what POV-Ray's half-float OpenEXR can hold.
inline constexpr float kHalfMax = 65504.0f;

/// Each value v becomes clean(v) · 2^exposure_ev, where clean(NaN) = 0, clean(v < 0) = 0 and
/// clean(v) = min(v, 65504) (so +inf becomes the largest half float): a stray NaN or infinity
/// from the renderer stays one wrong pixel instead of being spread over the frame by bloom.
/// exposure_ev in [−16, 16] stops (throws std::invalid_argument otherwise); +1 doubles the light.
void apply_exposure(RgbImage& image, double exposure_ev);

}  // namespace raintrace::film
