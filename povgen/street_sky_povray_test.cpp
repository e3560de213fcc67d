// night_street's skylight fill against its sky, with the real POV-Ray (label `povray`; skipped
// without it). POV-Ray lights nothing with its sky_sphere, so the template lights every surface
// with a little ambient instead (RT_Fill), standing for the overcast sky's light. A white
// Lambertian surface under sky of radiance L shows (1/π)∫L cos θ dΩ over the sky it sees; in the
// street the facades hide most of it, and the bright band near the horizon most of all. The fill
// must be no more than the sky sends the middle of the road. Until 2026-12-02 it was 0.012, nine
// times that and three times what the open sky would give: the shadows the lamps leave were
// lifted by light no sky sent ("lifted more evenly than one overhead sign would manage, so it
// looks like added fill", a blind viewer).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "povgen/povray_test_support.h"

namespace raintrace::povgen {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 720;  // the view from the road, equirectangular: 0.5° a pixel
constexpr int kHeight = 360;

// The street (preview: the same geometry, cheaper finishes) seen from the middle of the road,
// 26 m ahead of the default camera, by a spherical camera a few centimetres up; `sky` false
// blacks out the sky, so the two pictures differ by the sky the road sees.
std::string view_from_the_road(bool sky) {
  return std::string(
             "#version 3.7;\n"
             "global_settings { assumed_gamma 1 }\n"
             "#declare RT_Preview = 1;\n"
             "#declare RT_CameraPosition = <-1.2, 1.45, -6>;\n"
             "#include \"night_street.inc\"\n") +
         (sky ? "" : "sky_sphere { pigment { rgb 0 } }\n") +
         "#debug concat(\"fill \", str(RT_Fill, 0, 6), \"\\n\")\n"
         "camera { spherical angle 360 180 location <0, 0.05, 20> look_at <0, 0.05, 21> }\n";
}

TEST(PovRayStreetSky, FillIsNoMoreThanTheSkySendsTheRoad) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_street_sky");
  const std::string options =
      "+W" + std::to_string(kWidth) + " +H" + std::to_string(kHeight) + " -A";
  const std::vector<float> with =
      testing::trace_linear(dir, "sky", view_from_the_road(true), options);
  const std::vector<float> without =
      testing::trace_linear(dir, "dark", view_from_the_road(false), options);
  ASSERT_EQ(with.size(), 3u * kWidth * kHeight);
  ASSERT_EQ(without.size(), with.size());
  // trace_linear runs POV-Ray without -GA, so the #debug line is in the last log.
  const std::string log = read_file_bytes(dir / "povray.log");
  std::smatch match;
  ASSERT_TRUE(std::regex_search(log, match, std::regex(R"(fill ([0-9.]+))")))
      << "RT_Fill not printed";
  const double fill = std::stod(match[1]);

  // Row r looks at elevation 90° − (r + 0.5)·180°/H; a pixel covers cos(elevation)·dλ·dφ of
  // the sphere, and the road weights it by sin(elevation).
  const double step = M_PI / kHeight;
  double irradiance = 0.0;
  for (int row = 0; row < kHeight / 2; ++row) {
    const double elevation = M_PI / 2 - (row + 0.5) * step;
    const double weight = std::cos(elevation) * std::sin(elevation) * step * step / M_PI;
    for (int column = 0; column < kWidth; ++column) {
      const std::size_t i = 3u * (static_cast<std::size_t>(row) * kWidth + column);
      irradiance +=
          weight * (0.2126 * (with[i] - without[i]) + 0.7152 * (with[i + 1] - without[i + 1]) +
                    0.0722 * (with[i + 2] - without[i + 2]));
    }
  }
  std::printf("skylight fill %.4f; the sky's light on the middle of the road %.4f\n", fill,
              irradiance);
  EXPECT_GT(irradiance, 0.0) << "the road sees no sky";
  EXPECT_LE(fill, irradiance) << "the fill is more light than the sky sends the road";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace raintrace::povgen
