// A decoded image as plain floats, so the metrics, diff and report code can be tested on images
// built in memory and never need OpenImageIO in a header.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace raintrace::compare {

struct Image {
  int width = 0;     ///< pixels, >= 0
  int height = 0;    ///< pixels, >= 0
  int channels = 0;  ///< values per pixel, >= 0 (e.g. 3 = RGB, 4 = RGBA)
  /// Names of the channels ("R", "G", "B", "A", ...); may be empty for images built in memory.
  std::vector<std::string> channel_names;
  /// Interleaved values, row-major from the top-left pixel: (y * width + x) * channels + c.
  /// 8/16-bit files are normalised to [0, 1] (value / 255 or / 65535), as OpenImageIO does.
  std::vector<float> pixels;
  /// The file stores floating-point values (OpenEXR, HDR, float TIFF): scene-linear light, not
  /// display values (hdr_input.h says how such images are compared).
  bool scene_linear = false;
  /// The file's ImageDescription, e.g. a developed PNG's "raintrace develop: …".
  std::string description;

  Image() = default;
  Image(int w, int h, int c, float fill = 0.0f)
      : width(w), height(h), channels(c), pixels(std::size_t(w) * h * c, fill) {}

  float& at(int x, int y, int c) { return pixels[(std::size_t(y) * width + x) * channels + c]; }
  float at(int x, int y, int c) const {
    return pixels[(std::size_t(y) * width + x) * channels + c];
  }
  std::size_t pixel_count() const { return std::size_t(width) * height; }
};

}  // namespace raintrace::compare
