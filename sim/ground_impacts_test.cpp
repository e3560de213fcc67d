// Impacts sampled on the visible ground: flux, the volume's footprint, level of detail.
#include "sim/ground_impacts.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "sim/view_volume.h"
#include "sim/world.h"

namespace raintrace::sim {
namespace {

/// What an ImpactSampler needs, for a camera and a rain rate; the volume is [0.3, 1] m so its
/// footprint is small.
struct Rain {
  Camera camera;
  RainParams rain;
  ViewVolume view;
  DropSizeModel sizes;
  SpawnRegion region;
  GroundDetail detail;
  Rain(const Camera& c, double rate)
      : camera(c),
        rain(with_rate(rate)),
        view(camera, 0.3, 1.0),
        sizes(rain),
        region(view, 0.0, 2.0, glm::dvec3{0.0}, 0.0, 2.0),
        detail(camera) {}
  static RainParams with_rate(double rate) {
    RainParams r;
    r.rate_mm_per_h = rate;
    return r;
  }
};

TEST(GroundImpacts, FluxOnTheVisibleGroundIsRateTimesArea) {
  // With pixels so small that every impact is kept, the impacts in a slot are the number flux
  // ∫N(D)·v(D) dD times the sampled area times the slot: Poisson, so over ~10⁵ impacts the
  // count is within 1 %.
  Camera camera;
  camera.width_px = 100000;
  camera.look_at = {0.0, 0.0, 5.0};
  const Rain s(camera, 5.0);
  const ImpactSampler sampler(camera, 0.0, s.sizes, s.region, s.detail, 1);
  ASSERT_GT(sampler.area_m2(), 100.0);
  std::vector<GroundImpact> impacts;
  const int slots = 2;
  for (int slot = 0; slot < slots; ++slot) sampler.sample(slot, glm::dvec3{0.0}, impacts);
  const double expected =
      s.sizes.number_flux_per_m2_s() * sampler.area_m2() * slots * ImpactSampler::kSlot_s;
  ASSERT_GT(expected, 1e5);
  EXPECT_NEAR(static_cast<double>(impacts.size()) / expected, 1.0, 0.01);
  for (const GroundImpact& i : impacts) {
    EXPECT_EQ(i.weight, 1.0f);
    EXPECT_GE(i.time_s, 0.0);
    EXPECT_LT(i.time_s, slots * ImpactSampler::kSlot_s);
    EXPECT_FALSE(s.region.in_measure_area(glm::dvec3(i.position)));
  }
}

TEST(GroundImpacts, LevelOfDetailKeepsTheFluxAsWeight) {
  // At 640 pixels far impacts are thinned, but their weights still add up to the flux (the
  // heavy far weights make this noisier: 5 %).
  Camera camera;
  camera.look_at = {0.0, 1.0, 5.0};
  const Rain s(camera, 5.0);
  const ImpactSampler sampler(camera, 0.0, s.sizes, s.region, s.detail, 2);
  std::vector<GroundImpact> impacts;
  const int slots = 60;
  for (int slot = 0; slot < slots; ++slot) sampler.sample(slot, glm::dvec3{0.0}, impacts);
  double weight = 0.0;
  for (const GroundImpact& i : impacts) {
    weight += i.weight;
    EXPECT_NEAR(i.weight, 1.0 / s.detail.keep(glm::dvec3(i.position)), 1e-3 * i.weight);
  }
  const double expected =
      s.sizes.number_flux_per_m2_s() * sampler.area_m2() * slots * ImpactSampler::kSlot_s;
  EXPECT_NEAR(weight / expected, 1.0, 0.05);
  // Far fewer impacts simulated than happen.
  EXPECT_LT(static_cast<double>(impacts.size()), 0.2 * expected);
}

TEST(GroundImpacts, DetailIsFullWhileRipplesAreResolvedThenFallsWithPixelArea) {
  Camera camera;  // 640 px, 60°: a pixel is 1.80 mm per metre of distance
  const GroundDetail detail(camera);
  const glm::dvec3 eye = camera.position;
  EXPECT_NEAR(detail.pixel_m(eye + glm::dvec3{0.0, 0.0, 10.0}), 0.01804, 1e-4);
  EXPECT_DOUBLE_EQ(detail.keep(eye + glm::dvec3{0.0, 0.0, 4.0}), 1.0);
  const double at20 = detail.keep(eye + glm::dvec3{0.0, 0.0, 20.0});
  const double at40 = detail.keep(eye + glm::dvec3{0.0, 0.0, 40.0});
  EXPECT_NEAR(at20 / at40, 4.0, 1e-9);
}

TEST(GroundImpacts, SameSlotSameImpacts) {
  Camera camera;
  camera.look_at = {0.0, 1.0, 5.0};
  const Rain s(camera, 8.0);
  const ImpactSampler a(camera, 0.0, s.sizes, s.region, s.detail, 5);
  const ImpactSampler b(camera, 0.0, s.sizes, s.region, s.detail, 5);
  std::vector<GroundImpact> x, y;
  a.sample(17, glm::dvec3{1.0, 0.0, 0.0}, x);
  b.sample(17, glm::dvec3{1.0, 0.0, 0.0}, y);
  ASSERT_EQ(x.size(), y.size());
  ASSERT_GT(x.size(), 0u);
  for (std::size_t i = 0; i < x.size(); ++i) {
    EXPECT_EQ(x[i].key, y[i].key);
    EXPECT_EQ(x[i].position, y[i].position);
    EXPECT_EQ(x[i].velocity.x, 1.0f);  // the drops fall with the wind
  }
}

TEST(GroundImpacts, CameraLookingUpStillSeesImpactsOnTheGroundAhead) {
  // The view's bottom edge dips 9° below the horizon: the volume to 6 m never reaches the
  // ground (1.6 − 6·tan 9° > 0.6 m), yet the ground beyond is in view and gets impacts and
  // splashes, none of them from a drop of the volume.
  SimParams p;
  p.camera.look_at = {0.0, 3.0, 5.0};
  p.rain.far_m = 6.0;
  p.ripples.enabled = false;
  World world(p);
  world.advance_to(0.5);
  const Frame f = world.snapshot(1);
  EXPECT_GT(f.ground_impacts, 100.0);
  EXPECT_GT(f.splash_events, 10.0);
  EXPECT_GT(f.splashes.size(), 0u);
  // (The volume's drops land on its footprint below the view, out of sight.)
  const ViewVolume view(p.camera, 0.01, 1000.0);
  double nearest = 1e9;
  std::size_t seen = 0;
  for (const glm::vec3& pos : f.splashes.position) {
    if (!view.contains(glm::dvec3(pos))) continue;
    ++seen;
    nearest = std::min(nearest, glm::length(glm::dvec3(pos) - p.camera.position));
  }
  EXPECT_GT(seen, 0u);
  EXPECT_GT(nearest, p.rain.far_m);
}

}  // namespace
}  // namespace raintrace::sim
