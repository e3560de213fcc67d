// The ground as the camera sees it: pixel → ground geometry, the puddle mask, the ripple map.
#include "povgen/ground_maps.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "sim/ripples.h"
#include "tests/support/command.h"

namespace raintrace::povgen {
namespace {

/// Default camera (eye 1.6 m up at z = −5) looking down at (0, 0, 5), 320×180.
sim::Camera looking_down() {
  sim::Camera c;
  c.look_at = {0.0, 0.0, 5.0};
  return c;
}

TEST(GroundPixels, EachPixelHoldsTheGroundItsRayMeets) {
  const GroundPixels pixels(looking_down(), 320, 180, 0.0);
  std::size_t ground = 0;
  for (int j = 0; j < 180; ++j) {
    for (int i = 0; i < 320; ++i) {
      const std::size_t p = static_cast<std::size_t>(j) * 320 + i;
      if (!pixels.hits(p)) continue;
      ++ground;
      // Projecting the ground point back lands in the pixel's centre.
      double column = 0.0, row = 0.0;
      ASSERT_TRUE(pixels.project(pixels.x(p), pixels.z(p), column, row));
      EXPECT_NEAR(column, i + 0.5, 1e-3);
      EXPECT_NEAR(row, j + 0.5, 1e-3);
      // Seen at a slant, a pixel spans at least as much ground along the view as across.
      const sim::PixelSpan span = pixels.span(p);
      EXPECT_GE(span.along_m, span.across_m);
      EXPECT_NEAR(span.dir_x * span.dir_x + span.dir_z * span.dir_z, 1.0, 1e-5);
    }
  }
  // The camera looks 12.2° down with a half height of 17°: the top rows see sky.
  EXPECT_FALSE(pixels.hits(0));
  EXPECT_TRUE(pixels.hits(static_cast<std::size_t>(179) * 320));
  EXPECT_GT(ground, 320u * 120u);
}

TEST(GroundPixels, PixelSpanGrowsWithDistanceAndSlant) {
  // Straight ahead at (0, 0, 5): 10.1 m away, a pixel 2·tan 30°/320 = 3.6 mrad wide spans
  // ~3.6 cm across; the ray meets the ground at 9.1°, so along it spans ~6.4× that.
  const GroundPixels pixels(looking_down(), 320, 180, 0.0);
  double column = 0.0, row = 0.0;
  ASSERT_TRUE(pixels.project(0.0, 5.0, column, row));
  const std::size_t p = static_cast<std::size_t>(row) * 320 + static_cast<std::size_t>(column);
  const sim::PixelSpan span = pixels.span(p);
  const double distance = std::hypot(1.6, 10.0);
  EXPECT_NEAR(span.across_m, 10.0 * 2.0 * std::tan(M_PI / 6.0) / 320.0, 0.002);
  EXPECT_NEAR(span.along_m / span.across_m, distance / 1.6, 0.6);
  EXPECT_NEAR(span.dir_z, 1.0, 0.01);
}

TEST(PuddleMask, SharesFollowThePuddleFieldAndSkyIsDry) {
  const GroundPixels pixels(looking_down(), 320, 180, 0.0);
  sim::PuddleParams params;
  params.coverage = 0.3;
  const sim::PuddleField field(params, 1);
  const std::vector<float> mask = puddle_mask(pixels, field);
  std::size_t wet = 0, ground = 0;
  for (std::size_t p = 0; p < mask.size(); ++p) {
    if (!pixels.hits(p)) {
      EXPECT_EQ(mask[p], 0.0f);
      continue;
    }
    ++ground;
    EXPECT_EQ(mask[p] >= 0.5f, field.in_puddle(pixels.x(p), pixels.z(p)));
    wet += mask[p] >= 0.5f ? 1 : 0;
  }
  // Pixels are not spread evenly over the ground, but about a third of them see water.
  EXPECT_NEAR(static_cast<double>(wet) / static_cast<double>(ground), 0.3, 0.12);
}

TEST(RippleMap, ARingIsDrawnRoundItsImpactAndGrowsWithAge) {
  // A 4 mm drop's ring on a puddle seen from 3 m up through 2.7 mm pixels (the rings fully
  // resolved): the map's heights lie round the impact at the ring's radius, 18 mm more a tenth
  // of a second later. (Weighting by |h| over the growing circle puts the mean w²/r_f beyond
  // the front: +8.7 mm at 0.2 s, +5.8 mm at 0.3 s. Younger, the packet still reaches the centre.)
  sim::Camera camera;
  camera.position = {0.0, 3.0, -0.5};
  camera.look_at = {0.0, 0.0, 0.3};
  const GroundPixels pixels(camera, 1280, 720, 0.0);
  auto radius_of = [&](double age) {
    const sim::Ripple r = sim::make_ripple({0.3f, 0.0f, 0.0f}, 4e-3f, age, 6e-3, true, 0.5);
    RippleMap map;
    draw_ripples(pixels, {r}, map);
    EXPECT_FALSE(map.empty());
    double weight = 0.0, sum = 0.0;
    for (std::size_t p = 0; p < map.height_m.size(); ++p) {
      const double h = std::abs(map.height_m[p]);
      if (h == 0.0) continue;
      weight += h;
      sum += h * std::hypot(pixels.x(p) - 0.3, pixels.z(p));
      EXPECT_EQ(map.film[p], 0.0f);
    }
    return sum / weight;  // (|h|-weighted mean distance from the impact)
  };
  // The front at 0.2 and 0.3 s: the crater's edge (4 mm) plus the spread, 36.8 and 55.2 mm.
  const double front_early = 0.004 + 0.2 * sim::ripple_speed();
  const double front_late = 0.004 + 0.3 * sim::ripple_speed();
  const double w = 0.6 * sim::ripple_wavelength();
  const double early = radius_of(0.2), late = radius_of(0.3);
  EXPECT_NEAR(early, front_early + w * w / front_early, 0.002);
  EXPECT_NEAR(late, front_late + w * w / front_late, 0.002);
  EXPECT_NEAR(late - early, 0.1 * sim::ripple_speed() - (w * w / front_early - w * w / front_late),
              0.001);
}

TEST(RippleMap, FilmRipplesStirTheFilmNotTheHeights) {
  // A fresh dimple on the film (0.02 s: a patch of radius 2 + 4.6 + 10.3 mm, stir
  // (1 − 0.02/0.09)² = 0.6). 5 m away, where a pixel spans ~9 × 30 mm, the patch covers a few
  // pixels, each stirred 0.6; 25 m away it is smaller than its pixel (~45 mm × 0.7 m), which is
  // stirred by the share the patch covers. No height is drawn either way.
  const GroundPixels pixels(looking_down(), 640, 360, 0.0);
  auto film_of = [&](float z, int& touched) {
    const sim::Ripple r = sim::make_ripple({0.0f, 0.0f, z}, 2e-3f, 0.02, 0.3e-3, false, 0.5);
    RippleMap map;
    draw_ripples(pixels, {r}, map);
    EXPECT_FALSE(map.empty());
    float stirred = 0.0f;
    touched = 0;
    for (std::size_t p = 0; p < map.film.size(); ++p) {
      EXPECT_EQ(map.height_m[p], 0.0f);
      stirred = std::max(stirred, map.film[p]);
      touched += map.film[p] > 0.0f ? 1 : 0;
    }
    return stirred;
  };
  const sim::Ripple r = sim::make_ripple({0.0f, 0.0f, 0.0f}, 2e-3f, 0.02, 0.3e-3, false, 0.5);
  EXPECT_NEAR(sim::film_stir(r), std::pow(1.0 - 0.02 / 0.09, 2), 0.01);
  int touched = 0;
  EXPECT_NEAR(film_of(0.0f, touched), sim::film_stir(r), 1e-5);
  EXPECT_GE(touched, 2);
  EXPECT_LE(touched, 8);
  const double far = film_of(20.0f, touched);
  EXPECT_EQ(touched, 1);
  double column = 0.0, row = 0.0;
  ASSERT_TRUE(pixels.project(0.0, 20.0, column, row));
  const sim::PixelSpan span =
      pixels.span(static_cast<std::size_t>(row) * 640 + static_cast<std::size_t>(column));
  const double patch = M_PI * std::pow(sim::stirred_radius(r), 2);
  EXPECT_NEAR(far, sim::film_stir(r) * patch / (span.across_m * span.along_m), 1e-5);
  RippleMap map;
  // Out of view: nothing drawn.
  const sim::Ripple behind = sim::make_ripple({0.0f, 0.0f, -9.0f}, 2e-3f, 0.1, 6e-3, true, 0.5);
  draw_ripples(pixels, {behind}, map);
  EXPECT_EQ(*std::max_element(map.film.begin(), map.film.end()), 0.0f);
  EXPECT_EQ(*std::max_element(map.height_m.begin(), map.height_m.end()), 0.0f);
}

TEST(RippleMap, PngHoldsHeightsAndTheGroundsStateAsPovRayReadsThem) {
  // Gray = 0.5 + h / range; alpha how calm the film is, 1 − stir; 16 bits each, written as
  // they are (no alpha premultiplication by the writer).
  RippleMap map;
  map.width = 3;
  map.height = 1;
  map.height_m = {0.001f, -0.0005f, 0.0f};
  map.film = {0.0f, 0.25f, 1.0f};
  const std::filesystem::path path =
      raintrace::test_support::process_scratch_path("raintrace_ripple_map_test.png");
  write_ripple_png(path, map);
  auto in = OIIO::ImageInput::open(path.string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().nchannels, 2);
  EXPECT_EQ(in->spec().format, OIIO::TypeDesc::UINT16);
  std::vector<std::uint16_t> raw(6);
  // Raw file values: ask OIIO not to associate alpha on reading.
  in.reset();
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  in = OIIO::ImageInput::open(path.string(), &config);
  ASSERT_TRUE(in->read_image(0, 0, 0, 2, OIIO::TypeDesc::UINT16, raw.data()));
  EXPECT_EQ(raw, ripple_pixels(map));
  EXPECT_EQ(raw[0], static_cast<std::uint16_t>(std::lround((0.5 + 0.001 / 0.004) * 65535)));
  EXPECT_EQ(raw[1], 65535);  // calm: exactly the texture_map's end
  EXPECT_EQ(raw[3], static_cast<std::uint16_t>(std::lround(0.75 * 65535)));
  EXPECT_EQ(raw[5], 0);  // all stirred
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace raintrace::povgen
