// SSIM via separable Gaussian filtering of a, b, a², b² and a·b, fused into one horizontal and
// one vertical pass (O(2·11) per pixel instead of O(121) for a direct window sum).
#include "compare/ssim.h"

#include <fmt/core.h>
#include <algorithm>
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

float pixel_luminance(const float* p, int channels) {
  if (channels >= 3) return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
  return channels >= 1 ? p[0] : 0.0f;
}

// One row of luminance as doubles. Non-finite values would poison every window they touch;
// they count as black so SSIM stays a number (the error metrics report them).
void luminance_row(const Image& image, int y, double* out) {
  const float* p = &image.pixels[std::size_t(y) * image.width * image.channels];
  for (int x = 0; x < image.width; ++x, p += image.channels) {
    const float v = pixel_luminance(p, image.channels);
    out[x] = std::isfinite(v) ? v : 0.0;
  }
}

// Weighted sums of a, b, a², b², ab over offsets [k0, k1] around pa/pb, divided by the weight
// used (1 for a full window). Inlined with constant bounds for full windows so it unrolls.
inline void window_sums(const double* pa, const double* pb, int k0, int k1, const double* taps,
                        double* out) {
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0, s4 = 0, weight = 0;
  for (int k = k0; k <= k1; ++k) {
    const double t = taps[k + kRadius], a = pa[k], b = pb[k];
    const double ta = t * a, tb = t * b;
    s0 += ta;
    s1 += tb;
    s2 += ta * a;
    s3 += tb * b;
    s4 += ta * b;
    weight += t;
  }
  out[0] = s0 / weight;
  out[1] = s1 / weight;
  out[2] = s2 / weight;
  out[3] = s3 / weight;
  out[4] = s4 / weight;
}

}  // namespace

std::vector<float> luminance(const Image& image) {
  std::vector<float> y(image.pixel_count());
  for (std::size_t i = 0; i < y.size(); ++i)
    y[i] = pixel_luminance(&image.pixels[i * image.channels], image.channels);
  return y;
}

double ssim(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height) {
    throw std::invalid_argument(fmt::format("SSIM needs equal sizes, got {}x{} and {}x{}", a.width,
                                            a.height, b.width, b.height));
  }
  const int w = a.width, h = a.height;
  if (w == 0 || h == 0) return 1.0;
  const auto taps = gaussian_taps();
  const bool valid = w > 2 * kRadius && h > 2 * kRadius;
  const int x0 = valid ? kRadius : 0, x1 = valid ? w - kRadius : w;
  const int y0 = valid ? kRadius : 0, y1 = valid ? h - kRadius : h;
  const int cw = x1 - x0;

  // Rows stream through a ring of 11 rows of horizontal sums, so memory stays O(width) however
  // large the image: touching fresh memory (page faults) cost more than the arithmetic here.
  constexpr int kRing = 2 * kRadius + 1;
  std::vector<double> ring(std::size_t(kRing) * cw * 5);
  std::vector<double> la(w), lb(w);
  int next_row = 0;
  // Horizontal pass of one row over the centre columns, all five statistics at once (a, b, a²,
  // b², ab); windows cut at the border are renormalised, full windows are exactly the Gaussian.
  auto add_row = [&](int y) {
    luminance_row(a, y, la.data());
    luminance_row(b, y, lb.data());
    double* out = &ring[std::size_t(y % kRing) * cw * 5];
    for (int x = x0; x < x1; ++x, out += 5) {
      if (x >= kRadius && x < w - kRadius) {
        window_sums(&la[x], &lb[x], -kRadius, kRadius, taps.data(), out);
      } else {
        window_sums(&la[x], &lb[x], std::max(-kRadius, -x), std::min(kRadius, w - 1 - x),
                    taps.data(), out);
      }
    }
  };
  double total = 0.0;
  for (int y = y0; y < y1; ++y) {
    const int k0 = std::max(-kRadius, -y), k1 = std::min(kRadius, h - 1 - y);
    while (next_row <= y + k1) add_row(next_row++);
    // Vertical pass only at the centres, straight into the SSIM sum.
    for (int x = 0; x < cw; ++x) {
      double s[5] = {0, 0, 0, 0, 0}, weight = 0;
      for (int k = k0; k <= k1; ++k) {
        const double t = taps[k + kRadius];
        const double* in = &ring[(std::size_t((y + k) % kRing) * cw + x) * 5];
        for (int i = 0; i < 5; ++i) s[i] += t * in[i];
        weight += t;
      }
      const double ma = s[0] / weight, mb = s[1] / weight;
      const double sa = s[2] / weight - ma * ma, sb = s[3] / weight - mb * mb;
      const double sab = s[4] / weight - ma * mb;
      total +=
          ((2 * ma * mb + kC1) * (2 * sab + kC2)) / ((ma * ma + mb * mb + kC1) * (sa + sb + kC2));
    }
  }
  return total / (double(cw) * double(y1 - y0));
}

}  // namespace raintrace::compare
