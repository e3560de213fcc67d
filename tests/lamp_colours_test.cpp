// The environments' lights shine in their blackbodies' colours, with the real POV-Ray (label
// `povray`; skipped without it). A template declares each lamp's light as linear sRGB, the
// colour POV-Ray traces with (assumed_gamma 1, D65 white); the camera's white balance
// (film/white_balance.h) decides how warm it looks. Here POV-Ray reads the template and prints
// the colours, and each must be the blackbody that film/ computes at the lamp's temperature, at
// the luminance the template gives it. Until 2026-12-02 night_street's and closeup's templates
// held sRGB-encoded values (<1, 0.78, 0.52> for "3000 K", the light of a blackbody near
// 4700 K), and this failed.
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <string>
#include <vector>

#include "film/white_balance.h"
#include "povgen/povray_test_support.h"

namespace raintrace {
namespace {

using povgen::testing::debug_value_line;
using povgen::testing::debug_values;
using povgen::testing::folder_with_environment;
using povgen::testing::log_of;
using povgen::testing::run_povray;

/// The colours `names` as POV-Ray reads them from the built-in `environment`'s template, by
/// name. `knobs` are declared before it: what keeps the picture cheap.
std::map<std::string, std::array<double, 3>> environment_colours(
    const std::string& environment, const std::string& knobs,
    const std::vector<std::string>& names) {
  const auto dir = folder_with_environment("lamp_colours_" + environment, environment);
  std::string scene =
      "#version 3.7;\n"
      "global_settings { assumed_gamma 1 }\n" +
      knobs + "#include \"" + environment + ".inc\"\n" +
      "camera { location RT_CameraPosition look_at RT_CameraPosition + z }\n";
  for (const std::string& name : names) scene += debug_value_line(name, name, 3);
  povgen::write_file_atomic(dir / "colours.pov", scene);
  // Without -GA: #debug writes to the debug stream, which -GA would silence.
  EXPECT_EQ(run_povray(dir, "colours.pov +W8 +H8 +FE +Ocolours.exr"), 0) << log_of(dir);
  std::map<std::string, std::array<double, 3>> colours;
  for (const auto& [name, value] : debug_values(povgen::read_file_bytes(dir / "povray.log"))) {
    if (value.size() == 3) colours[name] = {value[0], value[1], value[2]};
  }
  return colours;
}

double luminance(const std::array<double, 3>& rgb) {
  return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}

struct Light {
  std::string name;
  double kelvin;
  double luminance;
};

/// Each light, as POV-Ray reads it from `environment`'s template (with `knobs` declared
/// before it), must be its blackbody's colour at its luminance.
void expect_blackbodies(const std::string& environment, const std::string& knobs,
                        const std::vector<Light>& lights) {
  std::vector<std::string> names;
  for (const Light& light : lights) names.push_back(light.name);
  const auto colours = environment_colours(environment, knobs, names);
  for (const Light& light : lights) {
    ASSERT_TRUE(colours.contains(light.name)) << light.name << " not printed";
    const std::array<double, 3>& colour = colours.at(light.name);
    EXPECT_NEAR(luminance(colour), light.luminance, 0.002) << light.name;
    const std::array<double, 3> blackbody = film::blackbody_rgb(light.kelvin);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(colour[c] / luminance(colour), blackbody[c], 0.002)
          << light.name << " channel " << c << " against " << light.kelvin << " K";
    }
  }
}

TEST(PovRayStreetLights, ShineInTheirBlackbodiesColours) {
  SKIP_WITHOUT_POVRAY();
  // The streetlights: warm-white LEDs, a neutral LED, high-pressure sodium (whose light lies by
  // the locus near 2000 K), all at one luminance, so a lamp's kind changes its hue only.
  // The windows' tungsten and LED light come from the same blackbodies, at luminance 1.
  const std::vector<Light> lights = {
      {"RT_LampColour", 3000, 0.81},   {"RT_LampNeutral", 4000, 0.81},
      {"RT_LampSodium", 2000, 0.81},   {"RT_Blackbody2000", 2000, 1.0},
      {"RT_Blackbody2700", 2700, 1.0}, {"RT_Blackbody3000", 3000, 1.0},
      {"RT_Blackbody4000", 4000, 1.0}};
  expect_blackbodies("night_street",
                     "#declare RT_CameraPosition = <0, 1.6, -5>;\n"
                     "#declare RT_LightsOnly = 1;\n",
                     lights);
}

// closeup's streetlights are night_street's warm-white LEDs; its windows are lit by tungsten or
// a warm LED, a cooler LED or a screen.
TEST(PovRayCloseupLights, ShineInTheirBlackbodiesColours) {
  SKIP_WITHOUT_POVRAY();
  const std::vector<Light> lights = {{"RT_LampColour", 3000, 0.81},
                                     {"RT_WindowWarm", 2700, 0.68},
                                     {"RT_WindowNeutral", 4000, 0.86},
                                     {"RT_WindowScreen", 8000, 0.64}};
  // Preview: no photon pass for the caustic.
  expect_blackbodies("closeup", "#declare RT_Preview = 1;\n", lights);
}

}  // namespace
}  // namespace raintrace
