// The iris's diffraction spikes: the share of light beyond an angle follows the edge-diffraction
// law (checked against the Airy pattern's exact encircled energy for a many-bladed iris), the
// light goes into rays at right angles to the blades' edges, falls off as 1/r², reaches farther
// in red than in blue, and is taken from the pixel that sends it.
#include "film/diffraction_spikes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "film/image_sums_test_support.h"

namespace raintrace::film {
namespace {

constexpr double kPi = std::numbers::pi;

/// A black frame with one pixel of `light` in every channel at its centre.
RgbImage point_light(int size, float light) {
  RgbImage image(size, size);
  for (int c = 0; c < 3; ++c) image.at(size / 2, size / 2, c) = light;
  return image;
}

/// Light (green) at r pixels from the centre of `image` in the direction `degrees`
/// counter-clockwise from the +x axis (image y grows downward), read at the nearest pixel.
double light_at(const RgbImage& image, double r, double degrees) {
  const double a = degrees * kPi / 180.0;
  const int x = int(std::lround(image.width / 2 + r * std::cos(a)));
  const int y = int(std::lround(image.height / 2 - r * std::sin(a)));
  return image.at(x, y, 1);
}

TEST(DiffractionSpikes, RaysAreOnePerEdgeNormalEvenBladesShareTheirs) {
  EXPECT_EQ(spike_rays(0), 0);
  EXPECT_EQ(spike_rays(6), 6);
  EXPECT_EQ(spike_rays(8), 8);
  EXPECT_EQ(spike_rays(5), 10);
  EXPECT_EQ(spike_rays(7), 14);
}

// For a circular opening the light outside radius v = πDθ/λ (the Airy pattern) is J0²(v) +
// J1²(v) (Born & Wolf, Principles of Optics §8.5.2), → 2/(πv) for large v. A 16-bladed iris is
// nearly a circle: P/A is 1/cos(π/16) = 1.0196 times the circle's. Its share beyond one pixel must
// match the exact Airy value at that pixel's angle within 3 % in each colour (the exact value
// wobbles about the asymptote by ~1/v²).
TEST(DiffractionSpikes, ShareBeyondAPixelMatchesTheAiryPatternForANearlyRoundIris) {
  const double fov_deg = 50.0;
  const int width = 1280;
  const Aperture iris{16, 0.008};
  const SpikeShare share = spike_share_beyond_one_pixel(iris, fov_deg, width);
  const double theta = 2.0 * std::tan(0.5 * fov_deg * kPi / 180.0) / width;
  const double wavelengths[3] = {610e-9, 550e-9, 465e-9};
  for (int c = 0; c < 3; ++c) {
    const double v = kPi * iris.diameter_m * theta / wavelengths[c];
    const double airy =
        std::pow(std::cyl_bessel_j(0.0, v), 2) + std::pow(std::cyl_bessel_j(1.0, v), 2);
    const double polygon_over_circle = 1.0 / std::cos(kPi / 16);
    EXPECT_NEAR(share.rgb[c], airy * polygon_over_circle, 0.03 * airy) << "channel " << c;
  }
  // A hexagon's perimeter over area is that of the circle through its corners over cos 30°.
  const SpikeShare hexagon = spike_share_beyond_one_pixel({6, 0.008}, fov_deg, width);
  EXPECT_NEAR(hexagon.rgb[1] / share.rgb[1], std::cos(kPi / 16) / std::cos(kPi / 6), 1e-12);
  // Half the opening, twice the share; red reaches farther than blue as λ does.
  const SpikeShare half = spike_share_beyond_one_pixel({16, 0.004}, fov_deg, width);
  EXPECT_NEAR(half.rgb[1] / share.rgb[1], 2.0, 1e-12);
  EXPECT_NEAR(share.rgb[0] / share.rgb[2], 610.0 / 465.0, 1e-12);
  EXPECT_EQ(spike_share_beyond_one_pixel({0, 0.008}, fov_deg, width).rgb[1], 0.0);
}

// Six blades: a hexagon with a flat bottom edge, so six rays — straight up and down and at ±30°
// from the horizontal on both sides — and nothing along the horizontal or at 60° between them.
TEST(DiffractionSpikes, SixBladesDrawSixRaysAtRightAnglesToTheEdges) {
  RgbImage image = point_light(401, 1e5f);
  apply_diffraction_spikes(image, {6, 0.002}, 50.0);
  for (const double ray : {90.0, 270.0, 30.0, 150.0, 210.0, 330.0}) {
    EXPECT_GT(light_at(image, 40, ray), 1e-3) << "no ray at " << ray << "°";
  }
  for (const double gap : {0.0, 180.0, 60.0, 120.0, 240.0, 300.0}) {
    EXPECT_EQ(light_at(image, 40, gap), 0.0) << "light between the rays at " << gap << "°";
  }
}

// Five blades: ten rays, one every 36° starting straight down (the bottom edge's normal) — so
// straight up as well, which a pentagon's own edges do not face.
TEST(DiffractionSpikes, FiveBladesDrawTenRays) {
  RgbImage image = point_light(401, 1e5f);
  apply_diffraction_spikes(image, {5, 0.002}, 50.0);
  for (int k = 0; k < 10; ++k) {
    EXPECT_GT(light_at(image, 40, 270.0 + 36.0 * k), 1e-3) << "ray " << k;
    EXPECT_EQ(light_at(image, 40, 288.0 + 36.0 * k), 0.0) << "between rays " << k;
  }
}

// Along a ray the samples are E(>r − ½) − E(>r + ½) with E ∝ 1/r: four times fainter at twice
// the distance, to within the discrete difference's (1 − 1/(4r²)) terms.
TEST(DiffractionSpikes, ARayFadesAsTheInverseSquareOfTheDistance) {
  RgbImage image = point_light(401, 1e5f);
  apply_diffraction_spikes(image, {6, 0.002}, 50.0);
  const double near = light_at(image, 20, 90.0);
  const double far = light_at(image, 40, 90.0);
  EXPECT_NEAR(near / far, 4.0, 0.01);
}

// The light the rays carry is taken from the pixel: the sum of every channel is kept while the
// rays stay inside the frame, and the pixel keeps 1 − 2·share of its light (E(>½ px) = 2·share).
TEST(DiffractionSpikes, APointKeepsItsLightAndLosesWhatItsRaysCarry) {
  const Aperture iris{6, 0.008};
  // Rays of a 1000 pixel end ~150 pixels out, where a sample falls under 1e-4 (their light
  // beyond is left in the pixel): all inside the frame.
  RgbImage image = point_light(801, 1e3f);
  apply_diffraction_spikes(image, iris, 50.0);
  const SpikeShare share = spike_share_beyond_one_pixel(iris, 50.0, 801);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(testing::channel_sum(image, c), 1e3, 0.01) << "channel " << c;
    const double kept = image.at(400, 400, c) / 1e3;
    EXPECT_NEAR(kept, 1.0 - 2.0 * share.rgb[c], 0.002) << "channel " << c;
  }
  // Red spreads more of its light than blue.
  EXPECT_LT(image.at(400, 400, 0), image.at(400, 400, 2));
}

// Rays that run off the frame take their light with them (it falls beside the sensor): a point
// two pixels below the top edge loses at least what its upward ray carries past 2.5 pixels,
// E(>2.5) = per-ray share / 2.5, and never more than all its rays carry.
TEST(DiffractionSpikes, RaysLeavingTheFrameTakeTheirLight) {
  const Aperture iris{6, 0.002};
  RgbImage image(101, 101);
  for (int c = 0; c < 3; ++c) image.at(50, 2, c) = 1e5f;
  apply_diffraction_spikes(image, iris, 50.0);
  const double share = spike_share_beyond_one_pixel(iris, 50.0, 101).rgb[1];
  const double lost = 1e5 - testing::channel_sum(image, 1);
  EXPECT_GT(lost, 0.99 * 1e5 * share / 6 / 2.5);
  EXPECT_LT(lost, 1e5 * 2 * share);
}

// Only lights above white spread: a frame of 0.9 everywhere, and a round opening on a lamp, are
// left as they were.
TEST(DiffractionSpikes, DimPixelsAndARoundOpeningLeaveTheImageAlone) {
  RgbImage dim(64, 64, 0.9f);
  const RgbImage before = dim;
  apply_diffraction_spikes(dim, {6, 0.008}, 50.0);
  EXPECT_EQ(dim.pixels, before.pixels);
  RgbImage lamp = point_light(65, 1e5f);
  const RgbImage lamp_before = lamp;
  apply_diffraction_spikes(lamp, {0, 0.0}, 50.0);
  EXPECT_EQ(lamp.pixels, lamp_before.pixels);
}

TEST(DiffractionSpikes, RejectsImpossibleIrises) {
  RgbImage image(8, 8);
  EXPECT_THROW(apply_diffraction_spikes(image, {2, 0.008}, 50.0), std::invalid_argument);
  EXPECT_THROW(apply_diffraction_spikes(image, {17, 0.008}, 50.0), std::invalid_argument);
  EXPECT_THROW(apply_diffraction_spikes(image, {6, 0.0}, 50.0), std::invalid_argument);
  EXPECT_THROW(apply_diffraction_spikes(image, {6, 0.008}, 180.0), std::invalid_argument);
  EXPECT_NO_THROW(apply_diffraction_spikes(image, {0, 0.0}, 50.0));
}

}  // namespace
}  // namespace raintrace::film
