// Conservative pyramid steps for bloom (contracts in pyramid.h). Loops run along rows of
// interleaved RGB floats so that the compiler vectorises them (this file is built with -O3: see
// CMakeLists.txt): bloom must stay a few milliseconds per frame (bench/film_bench).
#include "film/pyramid.h"

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace raintrace::film {

namespace {

/// Half-sample mirror of an index into [0, n): period 2n, so any tap lands inside even when the
/// kernel is wider than the image.
int mirror(int i, int n) {
  const int period = 2 * n;
  i %= period;
  if (i < 0) i += period;
  return i < n ? i : period - 1 - i;
}

constexpr float kBinomial[5] = {1.0f / 16, 4.0f / 16, 6.0f / 16, 4.0f / 16, 1.0f / 16};

/// Horizontal binomial pass of one row of `w` RGB pixels.
void blur_row(const float* in, float* out, int w) {
  for (int x = 0; x < w; ++x) {
    float sum[3] = {0, 0, 0};
    const bool inside = x >= 2 && x + 2 < w;
    for (int t = -2; t <= 2; ++t) {
      const float* p = in + std::size_t(inside ? x + t : mirror(x + t, w)) * 3;
      for (int c = 0; c < 3; ++c) sum[c] += kBinomial[t + 2] * p[c];
    }
    for (int c = 0; c < 3; ++c) out[std::size_t(x) * 3 + c] = sum[c];
  }
}

/// Bilinear 2× along one row: fine pixel 2k sits a quarter coarse pixel left of coarse pixel k,
/// 2k + 1 a quarter right; the neighbour beyond either end is the end pixel itself (clamp).
/// `fine` holds 2·w pixels.
void upsample_row(const float* coarse, float* fine, int w) {
  for (int k = 0; k < w; ++k) {
    const float* mid = coarse + std::size_t(k) * 3;
    const float* left = coarse + std::size_t(k > 0 ? k - 1 : 0) * 3;
    const float* right = coarse + std::size_t(k + 1 < w ? k + 1 : w - 1) * 3;
    for (int c = 0; c < 3; ++c) {
      fine[std::size_t(2 * k) * 3 + c] = 0.75f * mid[c] + 0.25f * left[c];
      fine[std::size_t(2 * k + 1) * 3 + c] = 0.75f * mid[c] + 0.25f * right[c];
    }
  }
}

}  // namespace

RgbImage downsample_half(const RgbImage& in) {
  RgbImage out((in.width + 1) / 2, (in.height + 1) / 2);
  const std::vector<float> zeros(std::size_t(in.width) * 3, 0.0f);
  for (int y = 0; y < out.height; ++y) {
    const float* row0 = &in.pixels[std::size_t(2 * y) * in.width * 3];
    // An odd last row pairs with black: its block holds the same light in twice the area.
    const float* row1 =
        2 * y + 1 < in.height ? &in.pixels[std::size_t(2 * y + 1) * in.width * 3] : zeros.data();
    float* o = &out.pixels[std::size_t(y) * out.width * 3];
    for (int x = 0; x < out.width; ++x) {
      const std::size_t a = std::size_t(2 * x) * 3;
      const bool pair = 2 * x + 1 < in.width;  // an odd last column pairs with black too
      for (int c = 0; c < 3; ++c) {
        const float right = pair ? row0[a + 3 + c] + row1[a + 3 + c] : 0.0f;
        o[std::size_t(x) * 3 + c] = 0.25f * (row0[a + c] + row1[a + c] + right);
      }
    }
  }
  return out;
}

RgbImage upsample_double(const RgbImage& in, int width, int height) {
  const auto fits = [](int fine, int coarse) {
    return fine == 2 * coarse || fine == 2 * coarse - 1;
  };
  if (!fits(width, in.width) || !fits(height, in.height)) {
    throw std::invalid_argument("upsample_double: " + std::to_string(in.width) + "x" +
                                std::to_string(in.height) + " cannot become " +
                                std::to_string(width) + "x" + std::to_string(height));
  }
  // Each output row blends two coarse rows widened to 2·w pixels. A padding column or row
  // beyond an odd target is folded back onto the last real one (the adjoint of
  // downsample_half's black padding), so no light is lost at the far edges.
  const std::size_t wide_floats = std::size_t(2 * in.width) * 3;
  const std::size_t kept = std::size_t(width) * 3;
  std::vector<float> mid(wide_floats), near(wide_floats);
  RgbImage out(width, height);
  for (int fy = 0; fy < 2 * in.height; ++fy) {
    const int k = fy / 2;
    const int other = fy % 2 == 0 ? (k > 0 ? k - 1 : 0) : (k + 1 < in.height ? k + 1 : k);
    upsample_row(&in.pixels[std::size_t(k) * in.width * 3], mid.data(), in.width);
    upsample_row(&in.pixels[std::size_t(other) * in.width * 3], near.data(), in.width);
    float* o = &out.pixels[std::size_t(fy < height ? fy : height - 1) * kept];
    for (std::size_t i = 0; i < kept; ++i) o[i] += 0.75f * mid[i] + 0.25f * near[i];
    if (kept < wide_floats) {
      for (std::size_t c = 0; c < 3; ++c) {
        o[kept - 3 + c] += 0.75f * mid[kept + c] + 0.25f * near[kept + c];
      }
    }
  }
  return out;
}

void add_blurred(RgbImage& sum, const RgbImage& in, float weight) {
  if (sum.width != in.width || sum.height != in.height) {
    throw std::invalid_argument("add_blurred: the sum and the image differ in size");
  }
  // Rows blurred across, kept in a ring of five (the vertical taps' reach), then summed down.
  const std::size_t row_floats = std::size_t(in.width) * 3;
  std::vector<float> ring(5 * row_floats);
  std::vector<int> ring_row(5, -1);
  const auto across = [&](int y) -> const float* {
    float* slot = &ring[std::size_t(y % 5) * row_floats];
    if (ring_row[std::size_t(y % 5)] != y) {
      blur_row(&in.pixels[std::size_t(y) * row_floats], slot, in.width);
      ring_row[std::size_t(y % 5)] = y;
    }
    return slot;
  };
  const float w0 = weight * kBinomial[0], w1 = weight * kBinomial[1], w2 = weight * kBinomial[2];
  for (int y = 0; y < in.height; ++y) {
    float* o = &sum.pixels[std::size_t(y) * row_floats];
    const float* a = across(mirror(y - 2, in.height));
    const float* b = across(mirror(y - 1, in.height));
    const float* c = across(y);
    const float* d = across(mirror(y + 1, in.height));
    const float* e = across(mirror(y + 2, in.height));
    for (std::size_t i = 0; i < row_floats; ++i) {
      o[i] += w0 * (a[i] + e[i]) + w1 * (b[i] + d[i]) + w2 * c[i];
    }
  }
}

RgbImage blur_binomial5(const RgbImage& in) {
  RgbImage out(in.width, in.height);
  add_blurred(out, in, 1.0f);
  return out;
}

}  // namespace raintrace::film
