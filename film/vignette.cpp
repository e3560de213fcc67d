// cos⁴ vignetting (contract in vignette.h).
#include "film/vignette.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace raintrace::film {

void apply_vignette(RgbImage& image, double strength, double fov_deg) {
  if (!(strength >= 0.0 && strength <= 1.0)) {
    throw std::invalid_argument("vignette strength must be in [0, 1]");
  }
  if (!(fov_deg > 0.0 && fov_deg < 180.0)) {
    throw std::invalid_argument("vignette field of view must be in (0, 180) degrees");
  }
  if (strength == 0.0) return;
  const double f = 0.5 * image.width / std::tan(0.5 * fov_deg * std::numbers::pi / 180.0);
  const double f2 = f * f;
  for (int y = 0; y < image.height; ++y) {
    const double dy = y + 0.5 - 0.5 * image.height;
    for (int x = 0; x < image.width; ++x) {
      const double dx = x + 0.5 - 0.5 * image.width;
      // cos²θ = f² / (f² + r²), so cos⁴θ needs no trigonometry.
      const double cos2 = f2 / (f2 + dx * dx + dy * dy);
      const float gain = float((1.0 - strength) + strength * cos2 * cos2);
      for (int c = 0; c < 3; ++c) image.at(x, y, c) *= gain;
    }
  }
}

}  // namespace raintrace::film
