// Energy-conserving glare as a sum of Gaussians built on a resolution pyramid (see bloom.h).
#include "film/bloom.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "film/pyramid.h"

namespace raintrace::film {

namespace {

/// The PSF's span: eight octaves, the finest one pixel wide at this reference width.
constexpr double kReferenceWidth = 1280.0;
constexpr int kLevelCount = 8;

}  // namespace

std::vector<BloomLevel> bloom_levels(int width) {
  const int offset = int(std::lround(std::log2(double(std::max(width, 1)) / kReferenceWidth)));
  std::vector<BloomLevel> levels;
  for (int l = offset; l < offset + kLevelCount; ++l) {
    if (l < 0) continue;
    const double four_l = std::ldexp(1.0, 2 * l);
    levels.push_back({l, std::sqrt(four_l + (four_l - 1.0) * 11.0 / 36.0), 1.0 / kLevelCount});
  }
  return levels;
}

RgbImage bloom(const RgbImage& in, double strength) {
  if (!(strength >= 0.0 && strength <= 1.0)) {
    throw std::invalid_argument("bloom strength must be in [0, 1]");
  }
  const std::vector<BloomLevel> levels = bloom_levels(in.width);
  if (strength == 0.0 || levels.empty() || in.pixel_count() == 0) return in;

  // coarse[l - 1] is level l (level 0 is `in` itself), down to the coarsest level used.
  const int top = levels.back().level;
  std::vector<RgbImage> coarse;
  for (int l = 1; l <= top; ++l) coarse.push_back(downsample_half(l == 1 ? in : coarse.back()));
  const auto level_image = [&](int l) -> const RgbImage& {
    return l == 0 ? in : coarse[std::size_t(l - 1)];
  };

  // Coarse to fine: add each used level's blur with its weight, carry the sum one level up.
  // Upsampling is linear, so carrying the running sum equals upsampling each level on its own.
  RgbImage scattered(level_image(top).width, level_image(top).height);
  std::size_t next = levels.size();  // levels[next - 1] is the finest level not yet added
  for (int l = top; l >= 0; --l) {
    const RgbImage& image = level_image(l);
    if (l < top) scattered = upsample_double(scattered, image.width, image.height);
    if (next > 0 && levels[next - 1].level == l) {
      add_blurred(scattered, image, float(levels[next - 1].weight));
      --next;
    }
  }

  // Light of levels finer than a pixel (left out of `levels`) stays where it is.
  double scattered_share = 0.0;
  for (const BloomLevel& level : levels) scattered_share += level.weight;
  const float keep = float(1.0 - strength * scattered_share);
  const float spread = float(strength);
  for (std::size_t i = 0; i < scattered.pixels.size(); ++i) {
    scattered.pixels[i] = keep * in.pixels[i] + spread * scattered.pixels[i];
  }
  return scattered;
}

}  // namespace raintrace::film
