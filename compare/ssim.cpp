// SSIM via separable Gaussian filtering of a, b, a², b² and a·b (five blurs instead of a
// per-window double loop: O(11) per pixel per map instead of O(121)).
#include "compare/ssim.h"

#include <fmt/core.h>
#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace raintrace::compare {

namespace {

constexpr int kRadius = 5;  // 11 taps
constexpr double kSigma = 1.5;
constexpr double kC1 = 0.01 * 0.01;  // (K1 L)², K1 = 0.01, L = 1
constexpr double kC2 = 0.03 * 0.03;  // (K2 L)², K2 = 0.03, L = 1

std::vector<double> gaussian_taps() {
  std::vector<double> taps(2 * kRadius + 1);
  double sum = 0.0;
  for (int i = -kRadius; i <= kRadius; ++i) {
    taps[i + kRadius] = std::exp(-(i * i) / (2.0 * kSigma * kSigma));
    sum += taps[i + kRadius];
  }
  for (double& t : taps) t /= sum;
  return taps;
}

// Separable blur; at the border the window is cut and its weights renormalised, which leaves
// interior ('valid') centres exactly the full-window Gaussian mean.
std::vector<double> blur(const std::vector<double>& src, int w, int h,
                         const std::vector<double>& taps) {
  std::vector<double> tmp(src.size()), dst(src.size());
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      double sum = 0.0, weight = 0.0;
      for (int k = -kRadius; k <= kRadius; ++k) {
        const int xx = x + k;
        if (xx < 0 || xx >= w) continue;
        sum += taps[k + kRadius] * src[std::size_t(y) * w + xx];
        weight += taps[k + kRadius];
      }
      tmp[std::size_t(y) * w + x] = sum / weight;
    }
  }
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      double sum = 0.0, weight = 0.0;
      for (int k = -kRadius; k <= kRadius; ++k) {
        const int yy = y + k;
        if (yy < 0 || yy >= h) continue;
        sum += taps[k + kRadius] * tmp[std::size_t(yy) * w + x];
        weight += taps[k + kRadius];
      }
      dst[std::size_t(y) * w + x] = sum / weight;
    }
  }
  return dst;
}

}  // namespace

std::vector<float> luminance(const Image& image) {
  std::vector<float> y(image.pixel_count());
  for (std::size_t i = 0; i < y.size(); ++i) {
    const float* p = &image.pixels[i * image.channels];
    if (image.channels >= 3) {
      y[i] = 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
    } else if (image.channels >= 1) {
      y[i] = p[0];
    }
  }
  return y;
}

double ssim(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height) {
    throw std::invalid_argument(fmt::format("SSIM needs equal sizes, got {}x{} and {}x{}", a.width,
                                            a.height, b.width, b.height));
  }
  const int w = a.width, h = a.height;
  if (w == 0 || h == 0) return 1.0;
  const std::vector<float> ya = luminance(a), yb = luminance(b);
  const std::size_t n = ya.size();
  std::vector<double> va(n), vb(n), aa(n), bb(n), ab(n);
  for (std::size_t i = 0; i < n; ++i) {
    // Non-finite luminance would poison every window it touches; treat it as black so SSIM
    // stays a number (the error metrics report the non-finite values).
    va[i] = std::isfinite(ya[i]) ? ya[i] : 0.0;
    vb[i] = std::isfinite(yb[i]) ? yb[i] : 0.0;
    aa[i] = va[i] * va[i];
    bb[i] = vb[i] * vb[i];
    ab[i] = va[i] * vb[i];
  }
  const auto taps = gaussian_taps();
  const auto mu_a = blur(va, w, h, taps), mu_b = blur(vb, w, h, taps);
  const auto e_aa = blur(aa, w, h, taps), e_bb = blur(bb, w, h, taps), e_ab = blur(ab, w, h, taps);

  const bool valid = w > 2 * kRadius && h > 2 * kRadius;
  const int x0 = valid ? kRadius : 0, x1 = valid ? w - kRadius : w;
  const int y0 = valid ? kRadius : 0, y1 = valid ? h - kRadius : h;
  double total = 0.0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const std::size_t i = std::size_t(y) * w + x;
      const double ma = mu_a[i], mb = mu_b[i];
      const double sa = e_aa[i] - ma * ma, sb = e_bb[i] - mb * mb, sab = e_ab[i] - ma * mb;
      total +=
          ((2 * ma * mb + kC1) * (2 * sab + kC2)) / ((ma * ma + mb * mb + kC1) * (sa + sb + kC2));
    }
  }
  return total / (double(x1 - x0) * double(y1 - y0));
}

}  // namespace raintrace::compare
