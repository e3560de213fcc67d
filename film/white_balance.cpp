// White balance by blackbody temperature (contract in white_balance.h).
#include "film/white_balance.h"

#include <stdexcept>

namespace raintrace::film {

std::array<double, 2> blackbody_chromaticity(double kelvin) {
  if (!(kelvin >= 1667.0 && kelvin <= 25000.0)) {
    throw std::invalid_argument("a blackbody's chromaticity is fitted for 1667–25000 K");
  }
  const double t = kelvin;
  const double x =
      t <= 4000.0 ? -0.2661239e9 / (t * t * t) - 0.2343589e6 / (t * t) + 0.8776956e3 / t + 0.179910
                  : -3.0258469e9 / (t * t * t) + 2.1070379e6 / (t * t) + 0.2226347e3 / t + 0.240390;
  const double y =
      t <= 2222.0   ? -1.1063814 * x * x * x - 1.34811020 * x * x + 2.18555832 * x - 0.20219683
      : t <= 4000.0 ? -0.9549476 * x * x * x - 1.37418593 * x * x + 2.09137015 * x - 0.16748867
                    : 3.0817580 * x * x * x - 5.87338670 * x * x + 3.75112997 * x - 0.37001483;
  return {x, y};
}

std::array<double, 3> blackbody_rgb(double kelvin) {
  const auto [x, y] = blackbody_chromaticity(kelvin);
  // XYZ at Y = 1, then IEC 61966-2-1's XYZ → linear sRGB.
  const double X = x / y;
  const double Z = (1.0 - x - y) / y;
  std::array<double, 3> rgb = {3.2406 * X - 1.5372 - 0.4986 * Z, -0.9689 * X + 1.8758 + 0.0415 * Z,
                               0.0557 * X - 0.2040 + 1.0570 * Z};
  if (!(rgb[0] > 0.0 && rgb[1] > 0.0 && rgb[2] > 0.0)) {
    throw std::invalid_argument("a blackbody this warm lies outside sRGB's gamut");
  }
  // The matrix keeps Y only up to its rounding: scale to luminance 1 exactly.
  const double luminance = 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
  for (double& c : rgb) c /= luminance;
  return rgb;
}

void apply_white_balance(RgbImage& image, double kelvin) {
  if (kelvin == 0.0) return;
  if (!(kelvin >= kMinWhiteBalanceK && kelvin <= kMaxWhiteBalanceK)) {
    throw std::invalid_argument("white balance must be 0 (off) or in [2000, 20000] K");
  }
  const std::array<double, 3> white = blackbody_rgb(kelvin);
  const std::array<float, 3> gain = {float(1.0 / white[0]), float(1.0 / white[1]),
                                     float(1.0 / white[2])};
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] *= gain[i % 3];
}

}  // namespace raintrace::film
