// An RGB picture as plain floats: the one type every film/ step takes and returns, so each step
// can be tested on images built in memory and no header needs OpenImageIO.
#pragma once

#include <cstddef>
#include <vector>

namespace raintrace::film {

/// Three interleaved channels (R, G, B), row-major from the top-left pixel. What the values mean
/// is the step's contract: scene-linear Rec. 709 radiance (any value >= 0, 1 = a diffuse white
/// under the key light, 0.18 = middle grey) before the display transform, display-encoded sRGB
/// in [0, 1] after it.
struct RgbImage {
  int width = 0;              ///< pixels, >= 0
  int height = 0;             ///< pixels, >= 0
  std::vector<float> pixels;  ///< (y · width + x) · 3 + channel

  RgbImage() = default;
  RgbImage(int w, int h, float fill = 0.0f)
      : width(w), height(h), pixels(std::size_t(w) * std::size_t(h) * 3, fill) {}

  std::size_t pixel_count() const { return std::size_t(width) * std::size_t(height); }
  float& at(int x, int y, int c) { return pixels[(std::size_t(y) * width + x) * 3 + c]; }
  float at(int x, int y, int c) const { return pixels[(std::size_t(y) * width + x) * 3 + c]; }
};

}  // namespace raintrace::film
