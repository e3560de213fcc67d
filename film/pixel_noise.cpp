// Counter-based pixel noise (contract in pixel_noise.h).
#include "film/pixel_noise.h"

namespace raintrace::film {

namespace {

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

}  // namespace

float clumped_noise(std::uint32_t x, std::uint32_t y, std::uint32_t frame, std::uint32_t seed) {
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

std::uint32_t fold_to_32(std::uint64_t value) { return std::uint32_t(value ^ (value >> 32)); }

}  // namespace raintrace::film
