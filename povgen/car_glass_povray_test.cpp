// The parked cars' glasshouse (night_street's RT_Car), with the real POV-Ray (ctest label
// `povray`; skipped without povray). POV-Ray's plane { N, D } lies at distance D along N made a
// unit vector; until 2026-12-05 the glasshouse's planes were written as if it lay where N·p = D,
// so the windscreen's top stood 19 cm behind the roof's front edge, the dash's top stood outside
// the glass, the glass roof showed behind and beside the painted one and the rear window stood
// upright. POV-Ray's own inside() says, point by point, whether the car holds each one.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "povgen/povray_test_support.h"

namespace raintrace::povgen {
namespace {

namespace fs = std::filesystem;

// A point of the car (its own frame: front toward +z, ground at y = 0, roof at 1.38-1.44 m, the
// glasshouse's top 10 cm inside the roof's edge) and whether the car should hold it.
struct Probe {
  const char* name;
  const char* point;
  bool inside;
};

constexpr Probe kProbes[] = {
    // The windscreen runs up to the roof's front edge (z = 0.3 at the glass's top, 1.42 m).
    {"glass_under_roof_front", "<0, 1.37, 0.30>", true},
    // Just above the dash's top, under the windscreen.
    {"glass_over_dash", "<0, 1.005, 0.85>", true},
    // The middle of the cabin.
    {"cabin", "<0, 1.2, -0.5>", true},
    // Behind the sloping rear window, below the roof's overhang.
    {"behind_rear_window", "<0, 1.3, -1.45>", false},
    // Beside the roof, outside the sides' tumblehome.
    {"beside_roof", "<0.6, 1.40, -0.5>", false},
};

TEST(PovRayCarGlass, TheGlasshouseMeetsTheRoofAndCoversTheDash) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_car_glass");
  std::string scene =
      "#version 3.7;\n"
      "global_settings { assumed_gamma 1 }\n"
      "#include \"night_street.inc\"\n"
      "camera { location <0, 2, -8> look_at <0, 1, 0> }\n"
      "#declare Car = object { RT_Car(RT_CarPaint(<0.1, 0.1, 0.1>)) }\n";
  for (const Probe& probe : kProbes) {
    scene += "#debug concat(\"probe " + std::string{probe.name} + " \", str(inside(Car, " +
             probe.point + "), 0, 0), \"\\n\")\n";
  }
  write_file_atomic(dir / "car.pov", scene);
  ASSERT_EQ(testing::run_povray(dir, "car.pov +W8 +H8 -A -F"), 0) << testing::log_of(dir);
  const std::string log = read_file_bytes(dir / "povray.log");
  fs::remove_all(dir);
  for (const Probe& probe : kProbes) {
    const std::string expected =
        "probe " + std::string{probe.name} + " " + (probe.inside ? "1" : "0") + "\n";
    EXPECT_NE(log.find(expected), std::string::npos)
        << probe.name << " " << probe.point << " should be " << (probe.inside ? "in" : "out of")
        << " the car; POV-Ray said:\n"
        << log.substr(0, 2000);
  }
}

}  // namespace
}  // namespace raintrace::povgen
