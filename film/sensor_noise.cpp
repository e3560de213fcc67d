// Shot and read noise of a digital camera (contract in sensor_noise.h).
#include "film/sensor_noise.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "film/documented_width.h"
#include "film/pixel_noise.h"
#include "film/softness.h"

namespace raintrace::film {

namespace {

constexpr double kMidGrey = 0.18;
/// Added to the seed for channel c (times c + 1): each channel draws its own noise, and none
/// draws the grain's (which uses the seed itself).
constexpr std::uint32_t kChannelSalt = 0x9E3779B9u;

/// The unit noise of every pixel and channel, before σ(L) scales it: each channel's photosites
/// draw their own (clumped by demosaicing), then the camera smooths the colour part into faint
/// blotches and keeps the luminance part (the channels' mean) as fine as it was drawn.
RgbImage camera_noise(int width, int height, std::uint32_t seed, std::uint32_t frame) {
  RgbImage noise(width, height), colour(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      float n[3];
      for (int c = 0; c < 3; ++c) {
        n[c] = clumped_noise(std::uint32_t(x), std::uint32_t(y), frame,
                             seed + kChannelSalt * std::uint32_t(c + 1));
      }
      const float mean = (n[0] + n[1] + n[2]) / 3.0f;
      for (int c = 0; c < 3; ++c) {
        noise.at(x, y, c) = mean;
        colour.at(x, y, c) = n[c] - mean;
      }
    }
  }
  // The same Gaussian as the lens's softness, in pixels of a 1920-wide frame.
  apply_softness(colour, kChromaSmoothingPx);
  for (std::size_t i = 0; i < noise.pixels.size(); ++i) noise.pixels[i] += colour.pixels[i];
  return noise;
}

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
  const RgbImage noise =
      camera_noise(image.width, image.height, fold_to_32(seed), fold_to_32(std::uint64_t(frame)));
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    float& v = image.pixels[i];
    v = std::max(0.0f, v + float(sensor_noise_rms(strength, image.width, v)) * noise.pixels[i]);
  }
}

}  // namespace raintrace::film
