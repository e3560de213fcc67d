// How much light night_street's wet road scatters back, with the real POV-Ray (ctest label
// `povray`; skipped without povray). A wet surface is darker than a dry one because light
// scattered up by the ground is mostly reflected back down at the water's surface (total internal
// reflection beyond 49°) and the ground absorbs part of it again: Lekner and Dorf, "Why some
// things are darker when wet", Applied Optics 27, 1278 (1988). The road's diffuse albedo must be
// what their model gives for asphalt as streets have it, and of a lamp's light it must reflect
// nothing beyond the water's mirror image and its glossy streak. The pavement's slabs lie under
// the same film and must do the same; the pavement's puddles must show the slabs beneath them.
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

constexpr int kRoadPixels = 200;

// Lekner and Dorf's wet albedo of a surface of dry albedo `dry` under a water layer of index n:
// light gets in (1 − r_e), the ground scatters `dry` of it, the water's surface lets 1 − ρ_i of
// that out and sends ρ_i back down, where the ground scatters `dry` of it again, and so on:
// (1 − r_e) · dry · (1 − ρ_i) / (1 − dry · ρ_i). r_e is water's reflectance for diffuse light
// from outside, 0.066 for n = 1.33; from inside, ρ_i = 1 − (1 − r_e) / n², 0.47 (their eq. 2).
double lekner_dorf_wet_albedo(double dry) {
  const double n = 1.33, outside = 0.066;
  const double inside = 1.0 - (1.0 - outside) / (n * n);
  return (1.0 - outside) * dry * (1.0 - inside) / (1.0 - dry * inside);
}

// Ground far behind the street's end (z = −200, where nothing stands) in `texture`, 40 m × 40 m,
// seen by `camera`. `sun` adds a parallel light of 1 from straight above. `before` is declared
// ahead of the template, as scene.inc declares the ground include's functions. `interior` gives
// the ground one (without, Fresnel's reflection is nil: the street's road plane has ior 1.33).
std::string far_ground_scene(const std::string& camera, const std::string& texture, bool sun,
                             const std::string& before = "", const std::string& interior = "") {
  return "#version 3.7;\n"
         "global_settings { assumed_gamma 1 }\n"
         "#declare RT_Preview = 0;\n" +
         before + "#include \"night_street.inc\"\n" + camera +
         "\nbox { <-20, 0, -220>, <20, 0.001, -180> texture { " + texture + " } " + interior +
         " }\n" +
         (sun ? "light_source { <0, 1000, -200> rgb 1 parallel point_at <0, 0, -200> }\n" : "");
}

// The ground seen straight down by an orthographic camera over all of it, so that its patches of
// lighter and darker asphalt or slabs average out.
std::string top_view_scene(const std::string& texture, bool sun, const std::string& before = "",
                           const std::string& interior = "") {
  return far_ground_scene(
      "camera { orthographic location <0, 5, -200> look_at <0, 0, -200> right x * 40 up z * 40 }",
      texture, sun, before, interior);
}

// The road so. Its own specular highlight, which such a light would put right where the camera
// looks, is turned off: it is the water's mirror image of the light, not light the road scatters;
// the rest of its finish (diffuse, the water's Fresnel reflection that conserve_energy takes from
// it) stays.
std::string road_scene(bool sun) { return top_view_scene("RT_Asphalt finish { specular 0 }", sun); }

// The ground in `texture` seen by an orthographic camera tilted `tilt_deg` from straight down,
// toward −z (the mirror images it sees lie up in the empty sky beyond the street's end), over
// 30 m × 30 m; 50 m away, so that its picture's plane stays above the ground.
std::string tilted_ground_scene(const std::string& texture, bool sun, double tilt_deg) {
  const double tilt = tilt_deg * M_PI / 180.0;
  return far_ground_scene("camera { orthographic location <0, " +
                              std::to_string(50.0 * std::cos(tilt)) + ", " +
                              std::to_string(-200.0 - 50.0 * std::sin(tilt)) +
                              "> look_at <0, 0, -200> right x * 30 up y * 30 }",
                          texture, sun);
}

// What a surface sends the camera from a light: the mean of lit − dark over the pictures of the
// scene with and without the light (POV-Ray's linear EXR), in units of the light's irradiance.
double scattered(const fs::path& dir, const std::string& name, const std::string& lit_scene,
                 const std::string& dark_scene, const std::string& options) {
  const auto lit = testing::trace_linear(dir, name + "_lit", lit_scene, options);
  const auto dark = testing::trace_linear(dir, name + "_dark", dark_scene, options);
  EXPECT_EQ(lit.size(), 3u * kRoadPixels * kRoadPixels);
  EXPECT_EQ(dark.size(), lit.size());
  if (lit.empty() || dark.size() != lit.size()) return 0.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < lit.size(); ++i) sum += lit[i] - dark[i];
  return sum / static_cast<double>(lit.size());
}

// What `texture` sends the camera 20° off the mirror direction of a light straight above, over
// its diffuse light (seen straight down with its own highlight turned off; POV-Ray's diffuse
// does not depend on the view). `what` names it in the printout.
double off_mirror_over_diffuse(const fs::path& dir, const std::string& texture,
                               const std::string& what) {
  const std::string options = testing::square_size(kRoadPixels) + " -A";
  const std::string flat = texture + " finish { specular 0 }";
  const double diffuse =
      scattered(dir, "top", top_view_scene(flat, true), top_view_scene(flat, false), options);
  const double tilted = scattered(dir, "tilted", tilted_ground_scene(texture, true, 20.0),
                                  tilted_ground_scene(texture, false, 20.0), options);
  std::printf("%s seen 20 degrees off the mirror direction: %.4f; diffuse light %.4f\n",
              what.c_str(), tilted, diffuse);
  return tilted / diffuse;
}

// A lamp's light the wet road reflects is Fresnel's share, once: the water's mirror image of the
// lens and the glossy streak around it, about 3° tall and 0.25° wide (night_street's
// RT_LampStreak). Seen 20° off the mirror direction of a light straight above, neither reaches
// the camera, so the road must show only its diffuse light, as bright as seen straight down with
// its highlight turned off (POV-Ray's diffuse does not depend on the view). With a highlight of
// the light sources as well (specular 0.6, roughness 0.02) it showed 12.2 times that (as
// drawn: 1.001).
TEST(PovRayWetRoad, ReflectsALampOnlyInItsMirrorImageAndStreak) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_wet_road_tilted");
  EXPECT_NEAR(off_mirror_over_diffuse(dir, "RT_Asphalt", "road"), 1.0, 0.05)
      << "the road reflects a lamp off its mirror direction";
  fs::remove_all(dir);
}

// The pavement's slabs are wet ground under the same water film as the road: a lamp's light they
// reflect is the film's mirror image of the lens and the streak every mirror sees, no more. Seen
// 20° off the mirror direction of a light straight above they must show only their diffuse
// light, as the road does. Until 2026-12-02 they had a Phong highlight of the lamps' light
// sources as well (specular 0.4, roughness 0.004), a second image of the same light.
TEST(PovRayWetPavement, ReflectsALampOnlyInItsMirrorImageAndStreak) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_wet_slabs_tilted");
  EXPECT_NEAR(off_mirror_over_diffuse(dir, "RT_Slabs", "slabs"), 1.0, 0.05)
      << "the slabs reflect a lamp off its mirror direction";
  fs::remove_all(dir);
}

// Asphalt pavements measured by Lawrence Berkeley National Laboratory's Heat Island Group have a
// dry albedo of about 0.04 when freshly paved, the bitumen coating the stones, rising within five
// years to a mean of 0.12, and none above 0.16, as traffic wears the bitumen off the aggregate.
// Wet, by Lekner and Dorf: 0.020 to 0.083. The street's road must scatter within that span.
TEST(PovRayWetRoad, ScattersWhatWetAsphaltDoes) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_wet_road");
  const std::string options = testing::square_size(kRoadPixels) + " -A";
  // Lit by irradiance 1 from straight above, a Lambertian surface of albedo A shows A in
  // POV-Ray's units (no 1/π on either side).
  const double albedo = scattered(dir, "top", road_scene(true), road_scene(false), options);
  const double fresh = lekner_dorf_wet_albedo(0.04), worn = lekner_dorf_wet_albedo(0.16);
  std::printf("wet road's albedo %.4f; wet asphalt %.4f (fresh) to %.4f (worn)\n", albedo, fresh,
              worn);
  EXPECT_GE(albedo, fresh);
  EXPECT_LE(albedo, worn);
  fs::remove_all(dir);
}

// A puddle on the pavement is the wet slab under a few millimetres of water, which absorb next to
// nothing: seen from straight above under a black sky (the water mirrors nothing), lit from above,
// it must scatter what the slabs do (docs/ground.md: "A puddle is the wet ground under a mirror,
// not a dark patch"). Its bed was near black until 2026-12-02: 0.25 of the slabs' light.
TEST(PovRayWetPavement, PuddlesShowTheSlabsBeneathTheirWater) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_wet_pavement");
  const std::string options = testing::square_size(kRoadPixels) + " -A";
  const std::string slabs = "RT_Slabs finish { specular 0 }";
  const std::string puddle = "RT_SlabPuddle finish { specular 0 }";
  const double slab_light =
      scattered(dir, "slabs", top_view_scene(slabs, true), top_view_scene(slabs, false), options);
  const double puddle_light = scattered(dir, "puddle", top_view_scene(puddle, true),
                                        top_view_scene(puddle, false), options);
  std::printf("pavement puddle %.4f against the slabs' %.4f\n", puddle_light, slab_light);
  EXPECT_NEAR(puddle_light / slab_light, 1.0, 0.1) << "the puddle's bed is not the slab beneath it";
  fs::remove_all(dir);
}

// Rain roughens standing water wherever it stands: the pavement's puddles must take the water
// surface the ground include draws for the road's (RT_PuddleHeight, its rings and the finer
// roughness of the impacts), not lie flat beside them. Seen from straight above under a light
// straight above, level water sends the light's highlight straight back to the camera; water
// tilted by the ground's height field, here a uniform slope of 0.2 (11°), sends it 23° away,
// where the highlight (roughness 0.002) has faded to nothing. Until 2026-12-02 the pavement's
// puddles were level whatever the ground said: the same light both ways.
TEST(PovRayWetPavement, PuddlesTakeTheRainsRoughnessFromTheGround) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_pavement_rain");
  const std::string options = testing::square_size(kRoadPixels) + " -A";
  const auto water = [](double slope) {
    return "#declare RT_PuddleHeight = function(x, y, z) { " + std::to_string(slope) + " * x }\n";
  };
  const double level = scattered(dir, "level", top_view_scene("RT_SlabPuddle", true, water(0)),
                                 top_view_scene("RT_SlabPuddle", false, water(0)), options);
  const double tilted = scattered(dir, "tilted", top_view_scene("RT_SlabPuddle", true, water(0.2)),
                                  top_view_scene("RT_SlabPuddle", false, water(0.2)), options);
  const double bed =
      scattered(dir, "bed", top_view_scene("RT_SlabPuddle finish { specular 0 }", true),
                top_view_scene("RT_SlabPuddle finish { specular 0 }", false), options);
  std::printf("pavement puddle under a light above: level %.4f, tilted %.4f, its bed alone %.4f\n",
              level, tilted, bed);
  // Level, the highlight (specular 0.6) adds to the bed's light; tilted, the bed's light is left.
  EXPECT_GT(level - bed, 0.3) << "level water sends no highlight back";
  EXPECT_NEAR(tilted, bed, 0.05 * bed) << "the puddle ignores the ground's water surface";
  fs::remove_all(dir);
}

// The rain moves the road's water film as it moves the puddles: in final frames the film's surface
// is the ground include's RT_RingHeight (the frame's rings of the impacts), averaged with the
// aggregate's relief, not a fixed undulation. Seen from straight above under a lit ceiling 20 m up
// whose light grows along x (10 + 0.25·x), level water mirrors the ceiling straight above it;
// tilted by a height field of uniform slope 0.2, the film, a normal averaged half and half with the
// aggregate's, turns ~0.1 and mirrors the ceiling ~4 m toward −x, a tenth darker. Until 2026-12-06
// the film's undulation was wrinkles of 0.5–0.8 m whatever the rain did (blind viewers: "a
// windblown pond, even when no rain is falling"): the same light both ways.
TEST(PovRayWetRoad, TheFilmTakesTheRainsSurfaceFromTheGround) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_road_rain");
  const std::string options = testing::square_size(kRoadPixels) + " -A";
  const auto mirrored = [&](const std::string& name, double slope) {
    // The ground include's two names the road reads, as scene.inc would declare them: the rings'
    // height field and (a stand-in) the aggregate's relief drawn no finer than the pixels.
    const std::string ground =
        "#declare RT_RingHeight = function(x, y, z) { " + std::to_string(slope) +
        " * x }\n"
        "#macro RT_ResolvedGranite(Amount, Scale) granite Amount scale 4 * Scale #end\n";
    // The road in the water of the street's road plane (ior 1.33, for Fresnel's share), under
    // the ceiling.
    const std::string scene =
        top_view_scene("RT_Asphalt", false, ground, "interior { ior 1.33 }") +
        "plane { y, 20 pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } scale 80 "
        "translate -40 * x } finish { ambient 0 diffuse 0 emission 20 } }\n";
    const auto picture = testing::trace_linear(dir, name, scene, options);
    EXPECT_EQ(picture.size(), 3u * kRoadPixels * kRoadPixels);
    double sum = 0.0;
    for (const float value : picture) sum += value;
    return picture.empty() ? 0.0 : sum / static_cast<double>(picture.size());
  };
  const double level = mirrored("level", 0.0);
  const double tilted = mirrored("tilted", 0.2);
  std::printf("the road's film under a ceiling lit along x: level %.4f, tilted %.4f\n", level,
              tilted);
  ASSERT_GT(level, 0.0);
  EXPECT_LT(tilted, 0.95 * level) << "the film ignores the ground's water surface";
  EXPECT_GT(tilted, 0.75 * level) << "the film tilts more than half the water's slope";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace raintrace::povgen
