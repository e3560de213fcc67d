// night_street's lit windows seen along the street, with the real POV-Ray (label `povray`;
// skipped without it). A window's glass sits 14 cm behind the wall's face, so from far enough
// along the street its jamb hides it; what a photograph still shows there is the reveal in front
// of the glass, lit by the room (blind viewers of the windows without it: "flat glowing
// rectangles pasted onto the bricks", the dark upper floors "blank, even planes").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "povgen/povray_test_support.h"

namespace raintrace::povgen {
namespace {

namespace fs = std::filesystem;

constexpr int kPixels = 200;
constexpr double kDistance = 20.0;  // from the camera to the window's middle
constexpr double kFovDeg = 10.0;

// One window 1.3 × 1.75 m in a wall far from the street (its face x = 1000, facing −x), lit by
// a white room at level 1 (`lit`) or dark, seen from `off_normal_deg` off the wall's normal,
// along the wall toward +z, against a black sky: the picture's light, its red summed over the
// pixels, linear.
double light_seen(const fs::path& dir, const std::string& name, bool lit, double off_normal_deg) {
  const double a = off_normal_deg * std::numbers::pi / 180.0;
  const std::string location = "<" + std::to_string(1000.0 - kDistance * std::cos(a)) +
                               ", 10.875, " + std::to_string(0.65 - kDistance * std::sin(a)) + ">";
  const std::string camera = "camera { perspective location " + location +
                             " look_at <1000, 10.875, 0.65> right x up y angle " +
                             std::to_string(kFovDeg) + " }\n";
  // The wall around the opening z 0–1.3, y 10–11.75, 30 cm thick, as RT_Building lays it, long
  // enough that the camera cannot see past its end to the room behind.
  const std::string wall =
      "union { box { <0, 0, -40>, <0.3, 10, 40> } box { <0, 11.75, -40>, <0.3, 20, 40> }\n"
      "        box { <0, 9.99, -40>, <0.3, 11.76, 0> } box { <0, 9.99, 1.3>, <0.3, 11.76, 40> }\n"
      "        pigment { rgb 0.1 } finish { ambient 0 diffuse 0.7 } }\n";
  const std::string scene =
      "#version 3.7;\n"
      "global_settings { assumed_gamma 1 }\n"
      "#declare RT_Preview = 1;\n"
      "#declare RT_CameraPosition = " +
      location +
      ";\n"
      "#include \"night_street.inc\"\n"
      "sky_sphere { pigment { rgb 0 } }\n"
      "union { " +
      wall + "RT_Window(0, 10, 1.3, 1.75, " + (lit ? "1" : "0") +
      ", RT_FrameDark, <1, 1, 1>, 1) translate x * 1000 }\n" + camera;
  const std::vector<float> rgb =
      testing::trace_linear(dir, name, scene, testing::square_size(kPixels) + " +A0.05 +AM2 +R3");
  double light = 0.0;
  for (std::size_t i = 0; i < rgb.size(); i += 3) light += rgb[i];
  return light;
}

// Seen square on, the room's light through the glass (its mean radiance over the opening) is
// the reference. Seen 86° off the wall's normal, past where the jamb hides the glass (84°), the
// lit window still sends light: its far jamb, 11 cm in front of the glass, at albedo 0.3 times
// the share of its cosine-weighted sky the glass fills and passes, 0.31, of the room's
// radiance. The dark window sends none.
TEST(PovRayLitWindow, SeenAlongTheStreetItsRevealShinesWithTheRoomsLight) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_lit_window");

  // Square on: the opening covers 1.3 × 1.75 m of the 3.5 m picture.
  const double metres_per_pixel =
      2.0 * kDistance * std::tan(kFovDeg / 2 * std::numbers::pi / 180) / kPixels;
  const double opening_pixels = 1.3 * 1.75 / (metres_per_pixel * metres_per_pixel);
  const double room =
      (light_seen(dir, "front_lit", true, 0.0) - light_seen(dir, "front_dark", false, 0.0)) /
      opening_pixels;

  // Along the street: the far jamb, 0.11 × 1.75 m, faces the camera 4° off its normal; the near
  // one's edge hides all of it but the 1.3 m / tan 86° = 9 cm nearest the wall's face.
  const double lit = light_seen(dir, "along_lit", true, 86.0);
  const double dark = light_seen(dir, "along_dark", false, 86.0);
  const double jamb_pixels = std::min(0.11, 1.3 / std::tan(86.0 * std::numbers::pi / 180)) *
                             std::cos(4.0 * std::numbers::pi / 180) * 1.75 /
                             (metres_per_pixel * metres_per_pixel);
  const double jamb = (lit - dark) / jamb_pixels;
  std::printf("the room through the glass %.4f; the far jamb seen at 86°: %.4f (%.3f of it)\n",
              room, jamb, jamb / room);
  ASSERT_GT(room, 0.0) << "no light through the glass square on";
  EXPECT_NEAR(jamb / room, 0.3 * 0.31, 0.3 * 0.31 * 0.25)
      << "the reveal's light against the room's seen through the glass";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace raintrace::povgen
