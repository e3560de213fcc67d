// The light closeup's drop focuses onto the car roof, with the real POV-Ray (label `povray`;
// skipped without it). The template traces the drops' caustics with photons shot from the lamp
// through the drops, and POV-Ray spreads each photon's light over the disc it gathers photons
// from. Light the drop refracts goes on away from the lamp: it lands on the paint under the drop
// or in its shadow, never back toward the lamp. Seen from straight above, the paint on the
// lamp's side of the drop, beyond its footprint, must gain nothing from the photons. Until
// 2026-12-02 the template left the gathering disc to POV-Ray, whose estimate for a scene a few
// millimetres across was about 2 mm: every bead stood in a glow twice its size, and the frame
// took twice as long to trace.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "povgen/povray_test_support.h"

namespace raintrace {
namespace {

namespace fs = std::filesystem;
using povgen::testing::folder_with_environment;
using povgen::testing::trace_linear;

constexpr int kPixels = 200;
constexpr double kView = 0.016;  // m: the square the camera sees, centred on the drop
// The least share of the light under the drop that its shadow must gain beyond the footprint:
// measured 0.59 with the lamp 15° up, −0.56 with it 29° up (without photons POV-Ray lets the
// lamp's light through a clear drop unbent, so the preview's shadow is the lighter one there).
constexpr double kShadowShare = 0.25;

// closeup's surroundings with none of its drops but one of the template's beads of radius 2 mm
// at the origin, seen straight down over kView × kView; `photons` 0 leaves the photons out, as
// the template does at preview.
std::string drop_from_above(bool photons) {
  return "#version 3.7;\n"
         "global_settings { assumed_gamma 1 }\n"
         "#declare RT_Preview = " +
         std::string(photons ? "0" : "1") +
         ";\n"
         "#declare RT_HeroDrops = 0;\n"
         "#include \"closeup.inc\"\n"
         "RT_Bead(<0, 0, 0>, 0.002, 1)\n"
         "camera { orthographic location <0, 0.05, 0> look_at <0, 0, 0> sky z\n"
         "         right x * " +
         std::to_string(kView) + " up z * " + std::to_string(kView) + " }\n";
}

// The photons' light on the paint around the bead, seen from above (photons on minus off, the
// three channels summed), in three places: under the bead (within its footprint); on the lamp's
// side beyond 1.2 footprints; and on the far side, in the bead's shadow, from the footprint out
// to two footprints.
struct CausticLight {
  double under = 0.0;
  double toward_lamp = 0.0;
  double in_shadow = 0.0;
};

CausticLight caustic_light(const std::string& name) {
  const fs::path dir = folder_with_environment(name, "closeup");
  const std::string options = povgen::testing::square_size(kPixels) + " -A";
  const std::vector<float> with = trace_linear(dir, "with", drop_from_above(true), options);
  const std::vector<float> without = trace_linear(dir, "without", drop_from_above(false), options);
  fs::remove_all(dir);
  EXPECT_EQ(with.size(), 3u * kPixels * kPixels);
  EXPECT_EQ(without.size(), with.size());
  if (with.size() != 3u * kPixels * kPixels || without.size() != with.size()) return {};

  // The bead's footprint on the roof: a sphere of radius R cut 0.26 R below its centre. The
  // picture's columns run along −x and its rows along −z (POV-Ray is left-handed), the lamp
  // stands toward <2, 1> in x and z.
  const double footprint = 0.002 * std::sqrt(1.0 - 0.26 * 0.26);
  const double lamp_x = 2.0, lamp_z = 1.0;
  const double pixel = kView / kPixels;
  CausticLight light;
  for (int row = 0; row < kPixels; ++row) {
    for (int column = 0; column < kPixels; ++column) {
      const double x = kView / 2 - (column + 0.5) * pixel;
      const double z = kView / 2 - (row + 0.5) * pixel;
      const std::size_t i = 3u * (static_cast<std::size_t>(row) * kPixels + column);
      const double added =
          (with[i] - without[i]) + (with[i + 1] - without[i + 1]) + (with[i + 2] - without[i + 2]);
      const double r = std::hypot(x, z);
      const bool lamp_side = x * lamp_x + z * lamp_z > 0;
      if (r <= footprint) light.under += added;
      if (r > 1.2 * footprint && lamp_side) light.toward_lamp += added;
      if (r > footprint && r <= 2.0 * footprint && !lamp_side) light.in_shadow += added;
    }
  }
  std::printf(
      "photons' light under the drop %.4g, on the lamp's side beyond it %.4g, in its "
      "shadow beyond it %.4g\n",
      light.under, light.toward_lamp, light.in_shadow);
  return light;
}

TEST(PovRayCloseupCaustic, DropsFocusTheirLightOnlyWhereItCanLand) {
  SKIP_WITHOUT_POVRAY();
  const CausticLight light = caustic_light("closeup_caustic");
  EXPECT_GT(light.under, 0.0) << "the photons bring no light";
  EXPECT_LT(light.toward_lamp, 0.02 * light.under)
      << "the photons' light spills back toward the lamp";
}

// The lamp stands 15° above the roof: the ray through the bead's centre, 0.26 R above the
// paint, lands 0.26 R / tan 15° = 0.97 R beyond the centre, at the footprint's rim, and the
// focused light beyond it spills out of the footprint into the near end of the shadow (a lamp
// 29° up, as until 2026-12-05, put it all under the bead, where the bead hides it).
TEST(PovRayCloseupCaustic, ALowLampThrowsTheDropsFocusIntoItsShadow) {
  SKIP_WITHOUT_POVRAY();
  const CausticLight light = caustic_light("closeup_caustic_shadow");
  EXPECT_GT(light.in_shadow, kShadowShare * light.under)
      << "the drop's focused light stays under the drop";
}

}  // namespace
}  // namespace raintrace
