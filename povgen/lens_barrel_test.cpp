// The lens barrel's rim (lens_barrel.h): where it stands, checked by following a pixel's rays
// from the opening to its point of focus, and when it is written at all.
#include "povgen/lens_barrel.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace raintrace::povgen {
namespace {

/// closeup's camera: 28.5 mm from its focus, a 1 mm opening, 20° across a 16:9 frame.
ExportParams closeup_look(double optical_vignetting) {
  ExportParams look;
  look.width = 640;
  look.height = 360;
  look.camera.position = {0.0024, 0.0048, -0.028};
  look.camera.look_at = {0.0, 0.0013, 0.0};
  look.camera.fov_deg = 20.0;
  look.aperture_m = 0.001;
  look.optical_vignetting = optical_vignetting;
  return look;
}

/// Where the ray from the opening's edge, on the side away from the axis, to the point of focus
/// of a pixel whose chief ray leaves the axis at tan θ = t crosses the plane `distance` in front
/// of the opening, measured from the axis (the camera's frame: the view along z).
double outer_ray_at(double t, double opening_radius, double focus, double distance) {
  const double start = opening_radius;  // x of the ray's start, on the opening
  const double aim = focus * t;         // x of the pixel's point of focus, at z = focus
  return start + (aim - start) * distance / focus;
}

TEST(LensBarrel, TheCornersChiefRayMeetsTheRim) {
  const ExportParams look = closeup_look(0.5);
  const double corner = std::tan(10.0 * M_PI / 180.0) * std::hypot(1.0, 360.0 / 640.0);
  EXPECT_NEAR(half_diagonal_tan(look), corner, 1e-12);
  const LensBarrel barrel = lens_barrel(look);
  EXPECT_NEAR(barrel.hole_radius_m, barrel.distance_m * corner, 1e-15);
  // In front of the opening, nearer than the focus (4.2 mm of 28.5 for closeup).
  EXPECT_GT(barrel.distance_m, 0.0);
  EXPECT_LT(barrel.distance_m, 0.2 * 0.0285);
}

TEST(LensBarrel, TheCutStartsWhereTheRaysOfAPixelFirstReachTheRim) {
  for (const double share : {0.25, 0.5, 1.0}) {
    const ExportParams look = closeup_look(share);
    const LensBarrel barrel = lens_barrel(look);
    const double focus = glm::length(look.camera.look_at - look.camera.position);
    const double opening_radius = look.aperture_m / 2.0;
    const double start = (1.0 - share) * half_diagonal_tan(look);
    // At the cut's start the outermost ray just grazes the hole's edge...
    EXPECT_NEAR(outer_ray_at(start, opening_radius, focus, barrel.distance_m), barrel.hole_radius_m,
                1e-9 * barrel.hole_radius_m)
        << "share " << share;
    // ...nearer the centre every ray passes, farther out some are stopped.
    EXPECT_LT(outer_ray_at(start - 0.01, opening_radius, focus, barrel.distance_m),
              barrel.hole_radius_m);
    EXPECT_GT(outer_ray_at(start + 0.01, opening_radius, focus, barrel.distance_m),
              barrel.hole_radius_m);
  }
}

TEST(LensBarrel, IsWrittenOnlyForATracedFocalBlur) {
  EXPECT_EQ(lens_barrel_text(closeup_look(0.0)), "");
  const std::string text = lens_barrel_text(closeup_look(0.5));
  EXPECT_EQ(text.find("disc{"), text.find('\n') + 1) << text;
  EXPECT_NE(text.find("no_shadow no_reflection"), std::string::npos) << text;

  ExportParams pinhole = closeup_look(0.5);
  pinhole.aperture_m = 0.0;
  EXPECT_THROW(lens_barrel_text(pinhole), std::invalid_argument);
  EXPECT_THROW(validate(pinhole), std::invalid_argument);
  ExportParams rain_only = closeup_look(0.5);
  rain_only.focal_blur = FocalBlur::rain;
  EXPECT_THROW(lens_barrel_text(rain_only), std::invalid_argument);
  EXPECT_THROW(validate(rain_only), std::invalid_argument);
}

}  // namespace
}  // namespace raintrace::povgen
