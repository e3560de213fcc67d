// The closeup's streetlight hangs where its light comes from, with the real POV-Ray (label
// `povray`; skipped without it). The lamp is out of the lens's view, but every drop mirrors it at
// its rim, so a lens drawn away from its light_source puts a glint on the drops where no light
// is: until 2026-12-05 the lens was flattened after it was placed, which moved it 1.1 m down
// with its height, and the big drop wore a row of stray white dots down its left rim.
#include <gtest/gtest.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "povgen/povray_test_support.h"

namespace raintrace {
namespace {

namespace fs = std::filesystem;
using povgen::testing::folder_with_environment;
using povgen::testing::trace_linear;

constexpr int kPixels = 32;

TEST(PovRayCloseupLamp, TheLensHangsAtItsLight) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = folder_with_environment("closeup_lamp", "closeup");
  // From the big drop's place on the roof, a 2° view (21 cm at the lamp's 6 m) centred on the
  // light_source's position, just below which the template hangs the lens.
  const std::string scene =
      "#version 3.7;\n"
      "global_settings { assumed_gamma 1 }\n"
      "#declare RT_Preview = 1;\n"
      "#declare RT_HeroDrops = 0;\n"
      "#include \"closeup.inc\"\n"
      "camera { location <0, 0.001, 0> look_at RT_Lamp - 0.06 * y angle 2 }\n";
  const std::vector<float> picture =
      trace_linear(dir, "lamp", scene, povgen::testing::square_size(kPixels) + " -A");
  fs::remove_all(dir);
  ASSERT_EQ(picture.size(), 3u * kPixels * kPixels);
  // The lens glows at 60 times the lamp's colour (red 1.43): ~86 in red. The misty air's glow
  // around it, which the camera sees whether the lens is there or not, gives about 3.
  const std::size_t centre = 3u * (static_cast<std::size_t>(kPixels / 2) * kPixels + kPixels / 2);
  EXPECT_GT(picture[centre], 20.0f) << "no lens where the lamp's light comes from";
}

}  // namespace
}  // namespace raintrace
