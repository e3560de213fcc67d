// The built-in environments' skylight fill against their own skies, with the real POV-Ray (label
// `povray`; skipped without it). POV-Ray lights nothing with its sky_sphere, so the templates
// light their surfaces with a little ambient instead (RT_Fill), standing for the overcast sky's
// light. A white Lambertian surface under sky of radiance L shows (1/π)∫L cos θ dΩ over the sky
// it sees; buildings hide most of it, and the bright band near the horizon most of all. The fill
// must be no more than the sky sends the surface it lights.
// - night_street: until 2026-12-02 the fill was 0.012, nine times what the sky sends the middle
//   of the road and three times what the open sky would give: the shadows the lamps leave were
//   lifted by light no sky sent ("lifted more evenly than one overhead sign would manage, so it
//   looks like added fill", a blind viewer).
// - closeup: until 2026-12-02 the car roof had ambient 0.01 and a shadowless skylight point
//   light worth another 0.012, with 0.0023 from the sky: the drops' shadows on the roof stood
//   in thirteen times the light the sky sends.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "povgen/povray_test_support.h"

namespace raintrace::povgen {
namespace {

namespace fs = std::filesystem;

constexpr int kSkyWidth = 720;  // the view from the surface, equirectangular: 0.5° a pixel
constexpr int kSkyHeight = 360;

// `preamble` (declarations and the environment's #include) seen by a spherical camera at
// `location`, looking along +z; `sky` false blacks out the sky, so the two pictures differ by
// the sky that spot sees. The template's RT_Fill is printed to the log.
std::string view_from(const std::string& preamble, const std::string& location, bool sky) {
  return "#version 3.7;\n"
         "global_settings { assumed_gamma 1 }\n" +
         preamble + (sky ? "" : "sky_sphere { pigment { rgb 0 } }\n") +
         testing::debug_value_line("fill", "RT_Fill") +
         "camera { spherical angle 360 180 location " + location + " look_at " + location +
         " + z }\n";
}

struct SkyFill {
  double fill = -1.0;        // the template's RT_Fill
  double irradiance = -1.0;  // luminance of E/π from the sky on a horizontal surface there
};

SkyFill measure_sky_fill(const fs::path& dir, const std::string& preamble,
                         const std::string& location) {
  const std::string options =
      "+W" + std::to_string(kSkyWidth) + " +H" + std::to_string(kSkyHeight) + " -A";
  const std::vector<float> with =
      testing::trace_linear(dir, "sky", view_from(preamble, location, true), options);
  const std::vector<float> without =
      testing::trace_linear(dir, "dark", view_from(preamble, location, false), options);
  SkyFill measured;
  if (with.size() != 3u * kSkyWidth * kSkyHeight || without.size() != with.size()) {
    ADD_FAILURE() << "no picture of the sky";
    return measured;
  }
  // trace_linear runs POV-Ray without -GA, so the #debug line is in the last log.
  const auto values = testing::debug_values(read_file_bytes(dir / "povray.log"));
  if (!values.contains("fill") || values.at("fill").size() != 1) {
    ADD_FAILURE() << "RT_Fill not printed";
    return measured;
  }
  measured.fill = values.at("fill")[0];

  // Row r looks at elevation 90° − (r + 0.5)·180°/H; a pixel covers cos(elevation)·dλ·dφ of
  // the sphere, and a horizontal surface weights it by sin(elevation).
  const double step = M_PI / kSkyHeight;
  measured.irradiance = 0.0;
  for (int row = 0; row < kSkyHeight / 2; ++row) {
    const double elevation = M_PI / 2 - (row + 0.5) * step;
    const double weight = std::cos(elevation) * std::sin(elevation) * step * step / M_PI;
    for (int column = 0; column < kSkyWidth; ++column) {
      const std::size_t i = 3u * (static_cast<std::size_t>(row) * kSkyWidth + column);
      measured.irradiance +=
          weight * (0.2126 * (with[i] - without[i]) + 0.7152 * (with[i + 1] - without[i + 1]) +
                    0.0722 * (with[i + 2] - without[i + 2]));
    }
  }
  return measured;
}

// The fill may be no more than the sky sends `surface` ("the road", "the roof").
void expect_fill_within_the_sky(const SkyFill& measured, const std::string& surface) {
  std::printf("skylight fill %.4f; the sky's light on %s %.4f\n", measured.fill, surface.c_str(),
              measured.irradiance);
  EXPECT_GT(measured.irradiance, 0.0) << surface << " sees no sky";
  EXPECT_LE(measured.fill, measured.irradiance)
      << "the fill is more light than the sky sends " << surface;
}

// The street (preview: the same geometry, cheaper finishes) seen from the middle of the road,
// 26 m ahead of the default camera, a few centimetres up.
TEST(PovRayStreetSky, FillIsNoMoreThanTheSkySendsTheRoad) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_street_sky");
  const SkyFill measured = measure_sky_fill(dir,
                                            "#declare RT_Preview = 1;\n"
                                            "#declare RT_CameraPosition = <-1.2, 1.45, -6>;\n"
                                            "#include \"night_street.inc\"\n",
                                            "<0, 0.05, 20>");
  expect_fill_within_the_sky(measured, "the middle of the road");
  fs::remove_all(dir);
}

// closeup's car roof (preview: no photons) seen from 4 mm above its paint, 30 cm in front of
// the drops; its fill is the only light in the drops' shadows besides the lamp's caustics.
TEST(PovRayCloseupSky, FillIsNoMoreThanTheSkySendsTheRoof) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_environment("povray_test_closeup_sky", "closeup");
  const SkyFill measured = measure_sky_fill(dir,
                                            "#declare RT_Preview = 1;\n"
                                            "#include \"closeup.inc\"\n",
                                            "<0, 0.004, -0.3>");
  expect_fill_within_the_sky(measured, "the roof");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace raintrace::povgen
