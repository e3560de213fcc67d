// Shot and read noise of a digital camera (contract in sensor_noise.h).
#include "film/sensor_noise.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "film/documented_width.h"
#include "film/pixel_noise.h"

namespace raintrace::film {

namespace {

constexpr double kMidGrey = 0.18;
/// Added to the seed for channel c (times c + 1): each channel draws its own noise, and none
/// draws the grain's (which uses the seed itself).
constexpr std::uint32_t kChannelSalt = 0x9E3779B9u;

}  // namespace

double sensor_noise_rms(double strength, int width, double linear) {
  const double s = at_width(strength, width);
  const double electron = kMidGrey * s * s;  // the value of one photoelectron
  return std::sqrt(electron * std::max(0.0, linear) +
                   electron * electron * kReadNoiseElectrons * kReadNoiseElectrons);
}

void apply_sensor_noise(RgbImage& image, double strength, std::uint64_t seed, std::int64_t frame) {
  if (!(strength >= 0.0 && strength <= kMaxSensorNoise)) {
    throw std::invalid_argument("sensor_noise must be in [0, 0.5]");
  }
  if (strength == 0.0) return;
  const std::uint32_t seed32 = fold_to_32(seed);
  const std::uint32_t frame32 = fold_to_32(std::uint64_t(frame));
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        const float n = clumped_noise(std::uint32_t(x), std::uint32_t(y), frame32,
                                      seed32 + kChannelSalt * std::uint32_t(c + 1));
        float& v = image.at(x, y, c);
        v = std::max(0.0f, v + float(sensor_noise_rms(strength, image.width, v)) * n);
      }
    }
  }
}

}  // namespace raintrace::film
