// Deterministic, luminance-dependent film grain (contract in grain.h).
#include "film/grain.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace raintrace::film {

namespace {

constexpr double kReferenceWidth = 1920.0;

/// pcg4d (Jarzynski & Olano, "Hash Functions for GPU Rendering", JCGT 9(3), 2020): a 4-D
/// integer hash built for pixel grids, four well-mixed 32-bit outputs per call.
struct U4 {
  std::uint32_t x, y, z, w;
};
U4 pcg4d(U4 v) {
  v.x = v.x * 1664525u + 1013904223u;
  v.y = v.y * 1664525u + 1013904223u;
  v.z = v.z * 1664525u + 1013904223u;
  v.w = v.w * 1664525u + 1013904223u;
  const auto mix = [](U4& u) {
    u.x += u.y * u.w;
    u.y += u.z * u.x;
    u.z += u.x * u.y;
    u.w += u.y * u.z;
  };
  mix(v);
  v.x ^= v.x >> 16;
  v.y ^= v.y >> 16;
  v.z ^= v.z >> 16;
  v.w ^= v.w >> 16;
  mix(v);
  return v;
}

/// Mean 0, variance 1: four uniforms on (0, 1) (each 24 bits, centred in its cell so the mean is
/// exactly ½) summed, centred at 2 and scaled by √(12/4) = √3.
float unit_noise(std::uint32_t x, std::uint32_t y, std::uint32_t frame, std::uint32_t seed) {
  const U4 h = pcg4d({x, y, frame, seed});
  constexpr float kScale = 1.0f / 16777216.0f;
  const float sum = (float(h.x >> 8) + 0.5f) * kScale + (float(h.y >> 8) + 0.5f) * kScale +
                    (float(h.z >> 8) + 0.5f) * kScale + (float(h.w >> 8) + 0.5f) * kScale;
  return (sum - 2.0f) * 1.7320508f;
}

/// Mean 0, variance 1, shared between neighbours as grains that span about a pixel are: the
/// pixel's unit_noise and its eight neighbours' weighted (1, 4, 1) ⊗ (1, 4, 1), divided by the
/// weights' root sum of squares (18). Neighbours correlate 8/18 ≈ 0.44 across a side, pixels two
/// apart 1/18.
float grain_noise(std::uint32_t x, std::uint32_t y, std::uint32_t frame, std::uint32_t seed) {
  constexpr float kWeight[3] = {1.0f, 4.0f, 1.0f};
  float sum = 0.0f;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      // Unsigned wrap-around at the image's edges is harmless: the hash only needs distinct
      // inputs.
      sum += kWeight[i] * kWeight[j] * unit_noise(x + i - 1, y + j - 1, frame, seed);
    }
  }
  return sum / 18.0f;
}

}  // namespace

double grain_rms(double strength, int width, double v) {
  const double c = std::clamp(v, 0.0, 1.0);
  return strength * (width / kReferenceWidth) * 2.0 * std::sqrt(c * (1.0 - c));
}

void apply_grain(RgbImage& image, double strength, std::uint64_t seed, std::int64_t frame) {
  if (!(strength >= 0.0 && strength <= kMaxGrain)) {
    throw std::invalid_argument("grain strength must be in [0, 0.5]");
  }
  if (strength == 0.0) return;
  // The hash takes 32-bit words: the 64-bit seed and frame are folded by XOR of their halves
  // (frames below 2^32 stay distinct).
  const auto seed32 = std::uint32_t(seed ^ (seed >> 32));
  const auto frame32 = std::uint32_t(std::uint64_t(frame) ^ (std::uint64_t(frame) >> 32));
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const float n = grain_noise(std::uint32_t(x), std::uint32_t(y), frame32, seed32);
      for (int c = 0; c < 3; ++c) {
        float& v = image.at(x, y, c);
        v = std::clamp(v + float(grain_rms(strength, image.width, v)) * n, 0.0f, 1.0f);
      }
    }
  }
}

}  // namespace raintrace::film
