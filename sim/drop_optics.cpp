// Geometric-optics scattering of a water sphere (see drop_optics.h).
#include "sim/drop_optics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace raintrace::sim {

DropScattering drop_scattering(double ior, int rays) {
  constexpr double pi = std::numbers::pi;
  constexpr int kBins = 180;
  constexpr int kOrders = 10;  // p = 0 (reflection) … 9; the rest is below 1e-9
  std::array<double, kBins> energy{};
  double total = 0.0;
  double cosine = 0.0;
  double forward = 0.0;
  double forward_cosine = 0.0;
  for (int n = 0; n < rays; ++n) {
    // Impact parameter b uniform in area: ring weight 2b·db over the unit disc.
    const double b = (n + 0.5) / rays;
    const double weight = 2.0 * b / rays;
    const double i = std::asin(b);
    const double r = std::asin(b / ior);
    const double ci = std::cos(i);
    const double cr = std::cos(r);
    const double rs = (ci - ior * cr) / (ci + ior * cr);
    const double rp = (ior * ci - cr) / (ior * ci + cr);
    const std::array<double, 2> reflectance{rs * rs, rp * rp};
    for (int p = 0; p < kOrders; ++p) {
      double share = 0.0;  // unpolarised: the mean over s and p
      for (const double R : reflectance) {
        share += 0.5 * (p == 0 ? R : (1.0 - R) * (1.0 - R) * std::pow(R, p - 1));
      }
      const double deviation = (p - 1) * pi + 2.0 * i - 2.0 * p * r;
      const double theta = std::fabs(std::remainder(deviation, 2.0 * pi));  // in [0, π]
      const int bin = std::min(kBins - 1, static_cast<int>(theta / pi * kBins));
      energy[static_cast<std::size_t>(bin)] += weight * share;
      total += weight * share;
      cosine += weight * share * std::cos(theta);
      if (theta < 0.5 * pi) {
        forward += weight * share;
        forward_cosine += weight * share * std::cos(theta);
      }
    }
  }
  DropScattering out;
  out.phase.resize(kBins);
  for (int k = 0; k < kBins; ++k) {
    const double solid_angle =
        2.0 * pi * (std::cos(k * pi / kBins) - std::cos((k + 1) * pi / kBins));
    out.phase[static_cast<std::size_t>(k)] =
        energy[static_cast<std::size_t>(k)] / total * 4.0 * pi / solid_angle;
  }
  out.asymmetry = cosine / total;
  out.forward_share = forward / total;
  out.forward_mean_cosine = forward > 0.0 ? forward_cosine / forward : 0.0;
  return out;
}

const DropScattering& water_drop_scattering() {
  static const DropScattering water = drop_scattering(kWaterIor, 20000);
  return water;
}

PovrayLobes fit_povray_lobes(const DropScattering& s) {
  // A·cos^b θ over the forward hemisphere: ∫ cos^b θ dΩ / 4π = 1 / (2(b + 1)), and its light's
  // mean cosine is (b + 1)/(b + 2).
  const double m = std::clamp(s.forward_mean_cosine, 0.51, 0.99);
  PovrayLobes lobes;
  lobes.brilliance = (2.0 * m - 1.0) / (1.0 - m);
  const double lobe_integral = 1.0 / (2.0 * (lobes.brilliance + 1.0));
  // P/4 per lobe (POV-Ray's light colour is E/π).
  lobes.back = s.forward_share / lobe_integral / 4.0;
  lobes.front = (1.0 - s.forward_share) / lobe_integral / 4.0;
  return lobes;
}

}  // namespace raintrace::sim
