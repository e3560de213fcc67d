// The glow around a streetlight (night_street's RT_LampGlow) follows the mist the scene declares,
// with the real POV-Ray (ctest label `povray`; skipped without povray). The glow is the lamp's
// light scattered by the air around it, so it is as strong as that air is dense: with ground fog
// (scene.inc declares RT_GroundFogDensity σ0 and RT_GroundFogDepth d) the fog where the lens
// stands, POV-Ray's profile σ0 / (1 + (h/d)²) at the lamps' height h = 6 m; without, the
// rain-soaked city air's 0.01 /m.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "povgen/output_folder.h"
#include "povgen/povray_test_support.h"
#include "povgen/templates.h"

namespace raintrace::povgen {
namespace {

namespace fs = std::filesystem;

using testing::log_of;
using testing::read_rgb;
using testing::run_povray;

constexpr int kSize = 64;

// A camera 20 m from a lens 5.88 m up, level with it, the street's lamps only (RT_LightsOnly),
// `fog` declared before the template. With `glow`, the lamp's glow sheet.
std::string glow_scene(const std::string& fog, bool glow) {
  return "#version 3.7;\n"
         "global_settings { assumed_gamma 1 }\n"
         "#declare RT_CameraPosition = <0, 5.88, -120>;\n"
         "#declare RT_LightsOnly = 1;\n" +
         fog + "#include \"night_street.inc\"\n" +
         "camera { perspective location RT_CameraPosition look_at <0, 5.88, -100> angle 20 }\n" +
         (glow ? "RT_LampGlow(<0, 5.88, -100>, <1, 1, 1>)\n" : "") + "\n";
}

// Mean red light the glow adds over rows 0.5–1.2 m below the lens, across 0.4 m: the cone under
// it, clear of the clip at 1 right at the lens.
double glow_below_lens(const std::vector<float>& with, const std::vector<float>& without) {
  // 20° over 64 pixels at 20 m: 0.110 m a pixel; the lens is at the middle row.
  double sum = 0.0;
  int n = 0;
  for (int y = kSize / 2 + 5; y <= kSize / 2 + 11; ++y) {
    for (int x = kSize / 2 - 2; x <= kSize / 2 + 2; ++x) {
      const std::size_t i = 3 * (static_cast<std::size_t>(y) * kSize + x);
      sum += with[i] - without[i];
      ++n;
    }
  }
  return sum / n;
}

TEST(PovRayLampGlow, TheGlowIsAsStrongAsTheMistAroundTheLamp) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::scratch_folder("povray_test_lamp_glow");
  fs::remove_all(dir);
  fs::create_directories(dir);
  write_file_atomic(dir / "night_street.inc", environment_template("night_street"));
  const std::string deep =
      "#declare RT_GroundFogDensity = 0.015;\n#declare RT_GroundFogDepth = 20;\n";
  const std::string shallow =
      "#declare RT_GroundFogDensity = 0.015;\n#declare RT_GroundFogDepth = 1.5;\n";
  const std::string none;
  const std::string size = " +W" + std::to_string(kSize) + " +H" + std::to_string(kSize);
  const auto render = [&](const std::string& name, const std::string& fog, bool glow) {
    write_file_atomic(dir / (name + ".pov"), glow_scene(fog, glow));
    EXPECT_EQ(run_povray(dir, name + ".pov" + size + " -A +FE +O" + name + ".exr"), 0)
        << name << ":\n"
        << log_of(dir);
    return read_rgb(dir / (name + ".exr"));
  };
  const auto background = render("background", none, false);
  const auto city_air = render("city_air", none, true);
  const auto deep_fog = render("deep_fog", deep, true);
  const auto shallow_fog = render("shallow_fog", shallow, true);
  ASSERT_EQ(background.size(), 3u * kSize * kSize);
  ASSERT_EQ(city_air.size(), background.size());
  ASSERT_EQ(deep_fog.size(), background.size());
  ASSERT_EQ(shallow_fog.size(), background.size());

  const double air = glow_below_lens(city_air, background);
  ASSERT_GT(air, 0.01) << "no glow under the lens";
  // 0.015 / (1 + (6/20)²) = 0.013761 and 0.015 / (1 + (6/1.5)²) = 0.000882, against 0.01.
  const double deep_ratio = glow_below_lens(deep_fog, background) / air;
  const double shallow_ratio = glow_below_lens(shallow_fog, background) / air;
  std::printf("glow in fog 20 m deep / city air: %.4f; 1.5 m deep: %.4f\n", deep_ratio,
              shallow_ratio);
  EXPECT_NEAR(deep_ratio, 1.3761, 0.02);
  EXPECT_NEAR(shallow_ratio, 0.0882, 0.005);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace raintrace::povgen
