// Diffraction spikes of a bladed iris (contract and physics in diffraction_spikes.h).
#include "film/diffraction_spikes.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace raintrace::film {

namespace {

constexpr double kPi = std::numbers::pi;
/// Wavelengths standing for R, G and B (m): the middle of each sRGB primary's band.
constexpr double kWavelengthM[3] = {610e-9, 550e-9, 465e-9};
/// A pixel spreads light only when one of its channels reaches this (scene-linear, exposed).
constexpr float kSpreadingLight = 1.0f;
/// A ray ends where its samples would add less than this: below Filmic's black.
constexpr double kFaintestSample = 1e-4;

/// Radians per pixel at the centre of a pinhole frame.
double pixel_angle(double fov_deg, int width) {
  return 2.0 * std::tan(0.5 * fov_deg * kPi / 180.0) / width;
}

void validate(const Aperture& aperture, double fov_deg) {
  if (!is_blade_count(aperture.blades)) {
    throw std::invalid_argument(
        fmt::format("aperture_blades must be 0 or in [3, {}]", kMaxApertureBlades));
  }
  if (aperture.blades != 0 && !(aperture.diameter_m > 0.0)) {
    throw std::invalid_argument("aperture_blades needs an opening: aperture_m must be > 0");
  }
  if (!(fov_deg > 0.0 && fov_deg < 180.0)) {
    throw std::invalid_argument("fov_deg must be in (0, 180)");
  }
}

/// Adds `light` at the point (x, y) in pixel-centre coordinates (pixel (i, j)'s centre is at
/// (i, j)), shared bilinearly among the four pixels around it; what falls outside is lost.
void splat(RgbImage& image, double x, double y, int channel, double light) {
  const int x0 = int(std::floor(x));
  const int y0 = int(std::floor(y));
  const double fx = x - x0;
  const double fy = y - y0;
  const double weights[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
  for (int i = 0; i < 4; ++i) {
    const int px = x0 + (i & 1);
    const int py = y0 + (i >> 1);
    if (px < 0 || py < 0 || px >= image.width || py >= image.height) continue;
    image.at(px, py, channel) += float(light * weights[i]);
  }
}

}  // namespace

int spike_rays(int blades) {
  if (blades == 0) return 0;
  return blades % 2 == 0 ? blades : 2 * blades;
}

SpikeShare spike_share_beyond_one_pixel(const Aperture& aperture, double fov_deg, int width) {
  validate(aperture, fov_deg);
  SpikeShare share;
  if (aperture.blades == 0 || width <= 0) return share;
  // A regular N-gon of circumradius R: P / A = 2 / (R cos(π/N)).
  const double radius = 0.5 * aperture.diameter_m;
  const double perimeter_over_area = 2.0 / (radius * std::cos(kPi / aperture.blades));
  const double theta = pixel_angle(fov_deg, width);
  for (int c = 0; c < 3; ++c) {
    share.rgb[c] = kWavelengthM[c] * perimeter_over_area / (2.0 * kPi * kPi * theta);
  }
  return share;
}

void apply_diffraction_spikes(RgbImage& image, const Aperture& aperture, double fov_deg) {
  validate(aperture, fov_deg);
  if (aperture.blades == 0 || image.pixel_count() == 0) return;
  const SpikeShare share = spike_share_beyond_one_pixel(aperture, fov_deg, image.width);
  const int rays = spike_rays(aperture.blades);
  const double theta = pixel_angle(fov_deg, image.width);
  // Each edge's normal: the bottom edge's points straight down, the others every 2π/N from it;
  // for N odd the opposite directions are rays too. Image y grows downward.
  std::vector<double> dx, dy;
  for (int k = 0; k < rays; ++k) {
    const double phi = -0.5 * kPi + 2.0 * kPi * k / rays;
    dx.push_back(std::cos(phi));
    dy.push_back(-std::sin(phi));
  }
  // The rays start past the Airy disc's first dark ring (1.22 λ/D), where the edge-diffraction
  // tail holds; nearer, the light stays. The same for every pixel of a channel.
  int first[3];
  for (int c = 0; c < 3; ++c) {
    const double airy_px = 1.22 * kWavelengthM[c] / (aperture.diameter_m * theta);
    first[c] = std::max(1, int(std::ceil(airy_px + 0.5)));
  }
  // Spread from a copy, so light a pixel receives is never spread again.
  const RgbImage source = image;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (std::max({source.at(x, y, 0), source.at(x, y, 1), source.at(x, y, 2)}) <
          kSpreadingLight) {
        continue;
      }
      for (int c = 0; c < 3; ++c) {
        const double light = source.at(x, y, c);
        // Per ray, E(>r) = per_ray / r pixels out.
        const double per_ray = light * share.rgb[c] / rays;
        double sent = 0.0;
        for (int k = 0; k < rays; ++k) {
          for (int r = first[c];; ++r) {
            const double sample = per_ray * (1.0 / (r - 0.5) - 1.0 / (r + 0.5));
            if (sample < kFaintestSample) break;
            // Pixel centres sit at whole indices here: the ray leaves (x, y)'s centre.
            splat(image, x + r * dx[std::size_t(k)], y + r * dy[std::size_t(k)], c, sample);
            sent += sample;
          }
        }
        image.at(x, y, c) -= float(sent);
      }
    }
  }
}

}  // namespace raintrace::film
