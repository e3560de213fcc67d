// Sums over test images that the film tests share: a channel's total light (which bloom,
// diffraction spikes and softness must keep) and how far a noise leaves a flat grey.
#pragma once

#include <cmath>
#include <cstddef>

#include "film/rgb_image.h"

namespace raintrace::film::testing {

/// Side of the flat test images the noise statistics are taken over: 262 144 pixels, the N the
/// tests' tolerances are worked out for.
inline constexpr int kStatsSide = 512;

/// Total of channel c over the image.
inline double channel_sum(const RgbImage& image, int c) {
  double sum = 0.0;
  for (std::size_t i = 0; i < image.pixel_count(); ++i) {
    sum += image.pixels[i * 3 + static_cast<std::size_t>(c)];
  }
  return sum;
}

/// Mean and RMS of a channel's departure from the flat level it started at.
struct Departure {
  double mean = 0.0;
  double rms = 0.0;
};
inline Departure departure_from(const RgbImage& image, float level, int c) {
  double sum = 0.0, sum2 = 0.0;
  for (std::size_t i = 0; i < image.pixel_count(); ++i) {
    const double d = image.pixels[i * 3 + static_cast<std::size_t>(c)] - double(level);
    sum += d;
    sum2 += d * d;
  }
  const double n = double(image.pixel_count());
  return {sum / n, std::sqrt(sum2 / n)};
}

}  // namespace raintrace::film::testing
