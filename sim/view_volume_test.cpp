// View frustum geometry.
#include "sim/view_volume.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "sim/random.h"

namespace raintrace::sim {
namespace {

TEST(ViewVolume, VolumeMatchesMonteCarlo) {
  Camera cam;
  cam.look_at = {3.0, 0.5, 4.0};  // yawed and pitched down
  const ViewVolume v(cam, 0.5, 6.0);
  // Sample a box around the frustum; the hit fraction × box volume estimates the volume.
  const double r = 6.5;
  const int n = 400000;
  int hits = 0;
  for (int k = 0; k < n; ++k) {
    const glm::dvec3 p = cam.position + glm::dvec3{(2 * uniform(1, Stream::fill, k, 0) - 1) * r,
                                                   (2 * uniform(1, Stream::fill, k, 1) - 1) * r,
                                                   (2 * uniform(1, Stream::fill, k, 2) - 1) * r};
    hits += v.contains(p);
  }
  const double estimate = static_cast<double>(hits) / n * 8 * r * r * r;
  EXPECT_NEAR(estimate, v.volume_m3(), 0.03 * v.volume_m3());
}

TEST(ViewVolume, ContainsWhatTheCameraSees) {
  const Camera cam;  // at (0, 1.6, −5) looking along +z
  const ViewVolume v(cam, 0.3, 12.0);
  EXPECT_TRUE(v.contains({0.0, 1.6, 0.0}));
  EXPECT_FALSE(v.contains({0.0, 1.6, -5.1}));  // behind
  EXPECT_FALSE(v.contains({0.0, 1.6, -4.8}));  // nearer than near
  EXPECT_FALSE(v.contains({0.0, 1.6, 7.5}));   // beyond far
  EXPECT_FALSE(v.contains({4.0, 1.6, 0.0}));   // right of 30° half-angle at 5 m (2.89 m)
  EXPECT_TRUE(v.contains({2.8, 1.6, 0.0}));
  EXPECT_FALSE(v.contains({std::nan(""), 1.6, 0.0}));
  EXPECT_GT(v.right().x, 0.99);  // +x is to the right looking along +z
}

TEST(ViewVolume, RejectsDegenerateCamera) {
  Camera cam;
  cam.look_at = cam.position;
  EXPECT_THROW(ViewVolume(cam, 0.3, 12.0), std::invalid_argument);
}

}  // namespace
}  // namespace raintrace::sim
