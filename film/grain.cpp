// Deterministic, luminance-dependent film grain (contract in grain.h).
#include "film/grain.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "film/documented_width.h"
#include "film/pixel_noise.h"

namespace raintrace::film {

double grain_rms(double strength, int width, double v) {
  const double c = std::clamp(v, 0.0, 1.0);
  return at_width(strength, width) * 2.0 * std::sqrt(c * (1.0 - c));
}

void apply_grain(RgbImage& image, double strength, std::uint64_t seed, std::int64_t frame) {
  if (!(strength >= 0.0 && strength <= kMaxGrain)) {
    throw std::invalid_argument("grain strength must be in [0, 0.5]");
  }
  if (strength == 0.0) return;
  const std::uint32_t seed32 = fold_to_32(seed);
  const std::uint32_t frame32 = fold_to_32(std::uint64_t(frame));
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const float n = clumped_noise(std::uint32_t(x), std::uint32_t(y), frame32, seed32);
      for (int c = 0; c < 3; ++c) {
        float& v = image.at(x, y, c);
        v = std::clamp(v + float(grain_rms(strength, image.width, v)) * n, 0.0f, 1.0f);
      }
    }
  }
}

}  // namespace raintrace::film
