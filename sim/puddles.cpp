// Procedural puddle field (see puddles.h).
#include "sim/puddles.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sim/random.h"

namespace raintrace::sim {
namespace {

struct Band {
  int waves;
  double wavenumber;  ///< in units of k0
  double weight;      ///< relative amplitude of each term
};
/// Broad wetter and drier areas, the puddles, their ragged edges.
constexpr Band kBands[] = {{12, 1.0 / 3.0, 0.6}, {20, 1.0, 1.0}, {12, 2.5, 0.35}};
/// Depth reaches depth_mm this far above the threshold, in standard deviations of the field.
constexpr double kDepthRamp = 0.4;
/// The threshold is the (1 − coverage) quantile of the field sampled on a grid this many
/// points square, spread over kSampleSpan puddle sizes (many of the broadest band's waves).
constexpr int kSamples = 128;
constexpr double kSampleSpan = 40.0;

}  // namespace

PuddleField::PuddleField(const PuddleParams& params, std::uint64_t seed)
    : m_film_m(params.film_mm * 1e-3), m_depth_m(params.depth_mm * 1e-3) {
  if (!(params.coverage > 0.0)) return;
  const double k0 = std::numbers::pi / params.size_m;
  std::uint64_t term = 0;
  double variance = 0.0, slope_variance = 0.0;
  for (const Band& band : kBands) {
    for (int i = 0; i < band.waves; ++i, ++term) {
      auto u = [&](int dim) { return uniform(seed, Stream::puddles, term, dim); };
      // Wavenumbers spread ±30 % around the band's so that no single wavelength dominates.
      const double k = band.wavenumber * k0 * (0.7 + 0.6 * u(0));
      const double direction = 2.0 * std::numbers::pi * u(1);
      m_waves.push_back({k * std::cos(direction), k * std::sin(direction),
                         2.0 * std::numbers::pi * u(2), band.weight});
      variance += 0.5 * band.weight * band.weight;
      // A cosine's slope along one horizontal direction has mean square a²k²/4 (cos² of the
      // angle to k averages 1/2, the cosine's own square 1/2).
      slope_variance += 0.25 * band.weight * band.weight * k * k;
    }
  }
  const double scale = 1.0 / std::sqrt(variance);
  for (Wave& w : m_waves) w.amplitude *= scale;
  m_edge = kFringeM * std::sqrt(slope_variance) * scale;

  std::vector<double> samples;
  samples.reserve(static_cast<std::size_t>(kSamples) * kSamples);
  const double step = kSampleSpan * params.size_m / kSamples;
  for (int i = 0; i < kSamples; ++i) {
    for (int j = 0; j < kSamples; ++j) samples.push_back(value(i * step, j * step));
  }
  const auto rank = static_cast<std::size_t>(
      std::clamp((1.0 - params.coverage) * static_cast<double>(samples.size()), 0.0,
                 static_cast<double>(samples.size() - 1)));
  std::nth_element(samples.begin(), samples.begin() + static_cast<std::ptrdiff_t>(rank),
                   samples.end());
  m_threshold = samples[rank];
}

double PuddleField::value(double x, double z) const {
  // Evaluated for every impact (10⁵–10⁶ per simulated second): single-precision cosines are
  // twice as fast, and the phase, reduced first in double, keeps them accurate to ~1e-7
  // anywhere on the ground.
  float f = 0.0f;
  for (const Wave& w : m_waves) {
    double phase = w.kx * x + w.kz * z + w.phase;
    phase -= 2.0 * std::numbers::pi * std::floor(phase * (0.5 / std::numbers::pi));
    f += static_cast<float>(w.amplitude) * std::cos(static_cast<float>(phase));
  }
  return f;
}

bool PuddleField::in_puddle(double x, double z) const {
  return !m_waves.empty() && value(x, z) > m_threshold;
}

double PuddleField::depth_m(double x, double z) const { return water_at(x, z).depth_m; }

PuddleField::Water PuddleField::water_at(double x, double z) const {
  Water w{m_film_m, false};
  if (m_waves.empty()) return w;
  const double above = value(x, z) - m_threshold;
  if (above <= 0.0) return w;
  w.puddle = true;
  w.depth_m = m_film_m + (m_depth_m - m_film_m) * std::min(1.0, above / kDepthRamp);
  return w;
}

double PuddleField::share(double x, double z) const {
  if (m_waves.empty()) return 0.0;
  return std::clamp(0.5 + (value(x, z) - m_threshold) / (2.0 * m_edge), 0.0, 1.0);
}

}  // namespace raintrace::sim
