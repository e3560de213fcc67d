// Procedural puddles: coverage, size, depth and the drawn share.
#include "sim/puddles.h"

#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>

namespace raintrace::sim {
namespace {

PuddleParams puddles(double coverage) {
  PuddleParams p;
  p.coverage = coverage;
  return p;
}

/// Share of a grid of points far from where the threshold was measured that lies in puddles.
double covered(const PuddleField& field, double size_m) {
  int in = 0, n = 0;
  for (double x = 500.0; x < 500.0 + 60.0 * size_m; x += 0.137 * size_m) {
    for (double z = -300.0; z < -300.0 + 60.0 * size_m; z += 0.141 * size_m, ++n) {
      in += field.in_puddle(x, z) ? 1 : 0;
    }
  }
  return static_cast<double>(in) / n;
}

TEST(Puddles, CoverTheRequestedShareOfTheGround) {
  for (const double c : {0.1, 0.25, 0.5}) {
    const PuddleField field(puddles(c), 3);
    EXPECT_NEAR(covered(field, 1.2), c, 0.05) << c;
  }
  EXPECT_TRUE(PuddleField(puddles(0.0), 3).empty());
  EXPECT_TRUE(PuddleField(puddles(-1.0), 3).empty());  // unresolved "environment default"
}

TEST(Puddles, DepthRisesFromTheFilmAtTheEdgeToDepthInside) {
  PuddleParams p = puddles(0.3);
  p.film_mm = 0.3;
  p.depth_mm = 6.0;
  const PuddleField field(p, 5);
  double deepest = 0.0;
  for (double x = 0.0; x < 20.0; x += 0.05) {
    for (double z = 0.0; z < 20.0; z += 0.05) {
      const double d = field.depth_m(x, z);
      deepest = std::max(deepest, d);
      if (field.in_puddle(x, z)) {
        EXPECT_GE(d, 0.3e-3);
        EXPECT_GE(field.share(x, z), 0.5);
      } else {
        EXPECT_DOUBLE_EQ(d, 0.3e-3);
        EXPECT_LE(field.share(x, z), 0.5);
      }
    }
  }
  EXPECT_DOUBLE_EQ(deepest, 6e-3);
}

TEST(Puddles, SizeSetsHowFarApartPuddlesAre) {
  // Count puddle edges crossed along a line: twice as large puddles, about half as many edges.
  auto edges = [](double size) {
    PuddleParams p = puddles(0.25);
    p.size_m = size;
    const PuddleField field(p, 9);
    int n = 0;
    bool was = field.in_puddle(0.0, 0.0);
    for (double x = 0.0; x < 400.0; x += 0.02) {
      const bool is = field.in_puddle(x, 1.0);
      n += is != was ? 1 : 0;
      was = is;
    }
    return n;
  };
  const double ratio = static_cast<double>(edges(1.0)) / edges(2.0);
  EXPECT_NEAR(ratio, 2.0, 0.4);
}

TEST(Puddles, DrawnShareSpansTheFringeAcrossAnEdge) {
  // share() rises from 0 to 1 over 2·kFringeM on average: edge() is kFringeM times the field's
  // rms slope along one direction, measured here by differences along x and along z.
  for (const double size : {0.5, 1.2, 4.0}) {
    PuddleParams p = puddles(0.25);
    p.size_m = size;
    const PuddleField field(p, 11);
    const double h = 1e-4 * size;
    double sum_x = 0.0, sum_z = 0.0;
    int n = 0;
    for (double x = 0.0; x < 30.0 * size; x += 0.113 * size) {
      for (double z = 0.0; z < 30.0 * size; z += 0.127 * size, ++n) {
        const double dx = (field.value(x + h, z) - field.value(x - h, z)) / (2.0 * h);
        const double dz = (field.value(x, z + h) - field.value(x, z - h)) / (2.0 * h);
        sum_x += dx * dx;
        sum_z += dz * dz;
      }
    }
    EXPECT_NEAR(std::sqrt(sum_x / n) * PuddleField::kFringeM / field.edge(), 1.0, 0.15) << size;
    EXPECT_NEAR(std::sqrt(sum_z / n) * PuddleField::kFringeM / field.edge(), 1.0, 0.15) << size;
    // Linear across the band, 0.5 on the edge.
    EXPECT_DOUBLE_EQ(
        field.share(0.3, 0.7),
        std::clamp(0.5 + (field.value(0.3, 0.7) - field.threshold()) / (2.0 * field.edge()), 0.0,
                   1.0));
  }
}

}  // namespace
}  // namespace raintrace::sim
