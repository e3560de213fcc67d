// A separable Gaussian blur in scene-linear light (contract in softness.h).
#include "film/softness.h"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "film/documented_width.h"

namespace raintrace::film {

namespace {

/// Below this σ the outer taps weigh under 1e-87: nothing to blur.
constexpr double kNegligibleSigma = 0.05;

/// Index i mirrored into [0, n): … 1 0 | 0 1 2 … n−1 | n−1 …, for |i| within one image length.
int mirror(int i, int n) {
  if (i < 0) i = -i - 1;
  if (i >= n) i = 2 * n - i - 1;
  return i;
}

std::vector<float> gaussian_taps(double sigma) {
  const int radius = std::max(1, int(std::ceil(3.0 * sigma)));
  std::vector<float> taps(std::size_t(2 * radius + 1));
  double sum = 0.0;
  for (int i = -radius; i <= radius; ++i) sum += std::exp(-0.5 * i * i / (sigma * sigma));
  for (int i = -radius; i <= radius; ++i) {
    taps[std::size_t(i + radius)] = float(std::exp(-0.5 * i * i / (sigma * sigma)) / sum);
  }
  return taps;
}

/// One pass along x (horizontal) or y, from `in` into `out` (same size).
void blur_pass(const RgbImage& in, RgbImage& out, const std::vector<float>& taps, bool along_x) {
  const int radius = int(taps.size() / 2);
  const int length = along_x ? in.width : in.height;
  for (int y = 0; y < in.height; ++y) {
    for (int x = 0; x < in.width; ++x) {
      float sum[3] = {0.0f, 0.0f, 0.0f};
      const int centre = along_x ? x : y;
      for (int k = -radius; k <= radius; ++k) {
        // Images narrower than the kernel: fold until inside (mirror handles one length).
        int i = centre + k;
        while (i < 0 || i >= length) i = mirror(i, length);
        const float w = taps[std::size_t(k + radius)];
        for (int c = 0; c < 3; ++c) sum[c] += w * (along_x ? in.at(i, y, c) : in.at(x, i, c));
      }
      for (int c = 0; c < 3; ++c) out.at(x, y, c) = sum[c];
    }
  }
}

}  // namespace

double softness_sigma_px(double softness, int width) { return at_width(softness, width); }

void apply_softness(RgbImage& image, double softness) {
  if (!(softness >= 0.0 && softness <= kMaxSoftness)) {
    throw std::invalid_argument("softness must be in [0, 4]");
  }
  const double sigma = softness_sigma_px(softness, image.width);
  if (sigma < kNegligibleSigma || image.pixel_count() == 0) return;
  const std::vector<float> taps = gaussian_taps(sigma);
  RgbImage across(image.width, image.height);
  blur_pass(image, across, taps, true);
  blur_pass(across, image, taps, false);
}

}  // namespace raintrace::film
