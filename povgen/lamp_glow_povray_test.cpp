// The glow around a streetlight (night_street's RT_LampGlow) follows the mist the scene declares,
// with the real POV-Ray (ctest label `povray`; skipped without povray). The glow is the lamp's
// light scattered by the air around it, so it is as strong as that air is dense: with ground fog
// (scene.inc declares RT_GroundFogDensity σ0 and RT_GroundFogDepth d) the fog where the lens
// stands, POV-Ray's profile σ0 / (1 + (h/d)²) at the lamps' height h = 6 m; without, the
// rain-soaked city air's 0.01 /m. Part of that light is the mist droplets' diffraction peak, a
// halo whose angular size is set by the droplets, not by the lamp's distance. Where the glows
// draw the lamps' light in the air, the lamps light no media, and the glows draw the share the
// rain beyond far_m scatters as well.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "povgen/output_folder.h"
#include "povgen/povray_test_support.h"

namespace raintrace::povgen {
namespace {

namespace fs = std::filesystem;

constexpr int kGlowSize = 64;

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

// Mean red light of `with` less `without` over rows row0–row1 and columns column0–column1,
// counted from the image's centre (where the lens is).
double glow_over(const std::vector<float>& with, const std::vector<float>& without, int row0,
                 int row1, int column0, int column1) {
  double sum = 0.0;
  int n = 0;
  for (int y = kGlowSize / 2 + row0; y <= kGlowSize / 2 + row1; ++y) {
    for (int x = kGlowSize / 2 + column0; x <= kGlowSize / 2 + column1; ++x) {
      const std::size_t i = 3 * (static_cast<std::size_t>(y) * kGlowSize + x);
      sum += with[i] - without[i];
      ++n;
    }
  }
  return sum / n;
}

// Mean red light the glow adds over rows 0.5–1.2 m below the lens, across 0.4 m: the cone under
// it, clear of the clip at 1 right at the lens (20° over 64 pixels at 20 m: 0.110 m a pixel).
double glow_below_lens(const std::vector<float>& with, const std::vector<float>& without) {
  return glow_over(with, without, 5, 11, -2, 2);
}

TEST(PovRayLampGlow, TheGlowIsAsStrongAsTheMistAroundTheLamp) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_lamp_glow");
  const std::string deep =
      "#declare RT_GroundFogDensity = 0.015;\n#declare RT_GroundFogDepth = 20;\n";
  const std::string shallow =
      "#declare RT_GroundFogDensity = 0.015;\n#declare RT_GroundFogDepth = 1.5;\n";
  const std::string none;
  const std::string options = testing::square_size(kGlowSize) + " -A";
  const auto render = [&](const std::string& name, const std::string& fog, bool glow) {
    return testing::trace_linear(dir, name, glow_scene(fog, glow), options);
  };
  const auto background = render("background", none, false);
  const auto city_air = render("city_air", none, true);
  const auto deep_fog = render("deep_fog", deep, true);
  const auto shallow_fog = render("shallow_fog", shallow, true);
  ASSERT_EQ(background.size(), 3u * kGlowSize * kGlowSize);
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

// A camera 1.45 m up, `distance` m before a lens 5.88 m up, looking at it; only the diffraction
// peak of the lamp's glow (share `share`), the mist's drift held even.
std::string halo_scene(double distance, double share) {
  const std::string d = std::to_string(distance);
  return "#version 3.7;\n"
         "global_settings { assumed_gamma 1 }\n"
         "#declare RT_CameraPosition = <0, 1.45, -" +
         d +
         ">;\n"
         "#declare RT_LightsOnly = 1;\n"
         "#declare RT_AureoleShare = 0;\n"
         "#declare RT_DiffractionShare = " +
         std::to_string(share) +
         ";\n"
         "#include \"night_street.inc\"\n"
         "#undef RT_MistDrift\n"
         "#declare RT_MistDrift = function { 0.5 }\n"  // 0.4 + 1.2 · 0.5 = 1
         "camera { perspective location RT_CameraPosition look_at <0, 5.88, 0> right x up y "
         "angle 10 }\n"
         "RT_LampGlow(<0, 5.88, 0>, <1, 1, 1>)\n";
}

// Airy's pattern holds half its light within k·a·ψ = v: 1 − J0(v)² − J1(v)² = 1/2.
double airy_half_energy() {
  double lo = 1.0, hi = 2.5;
  for (int i = 0; i < 60; ++i) {
    const double v = 0.5 * (lo + hi);
    const double inside =
        1.0 - std::pow(std::cyl_bessel_j(0.0, v), 2) - std::pow(std::cyl_bessel_j(1.0, v), 2);
    (inside < 0.5 ? lo : hi) = v;
  }
  return lo;
}

// The diffraction halo of mist droplets of radius 5 µm in green light, single-scattered along
// the line of sight: radiance σ_d · 2L · cos θ_n · F(ρ/D) / ρ at a ray passing ρ from the lens,
// D from the camera, F(γ) = ∫γ..π p(ψ) dψ for the Henyey-Greenstein lobe with Airy's half-energy
// angle (its own is √3·(1 − g)/√g). Pixels beside the lens, where the ray meets the glow's sheet
// (25 cm behind the lens), must show it within 5 % at the same angles from lamps 20, 30 and 100 m
// away: the halo's size is the droplets', whatever the distance.
TEST(PovRayLampGlow, MistDiffractsAHaloAsWideAsItsDropletsMakeIt) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_lamp_halo");
  const double k_a = 2.0 * M_PI * 5e-6 / 0.55e-6;
  const double width = airy_half_energy() / (std::sqrt(3.0) * k_a);  // (1 − g)/√g
  const double root_g = 0.5 * (-width + std::sqrt(width * width + 4.0));
  const double g = root_g * root_g;
  const auto lobe = [&](double gamma) {  // F(γ), small angles
    return (1 + g) / (4 * M_PI * (1 - g) * root_g) *
           (1 - root_g * gamma / std::sqrt((1 - g) * (1 - g) + g * gamma * gamma));
  };
  std::printf("mist droplets of 5 µm: g = %.4f, half the halo within %.2f°\n", g,
              std::sqrt(3.0) * width * 180 / M_PI);
  constexpr int kHalo = 200;
  const std::string options = testing::square_size(kHalo) + " -A";
  const double lens_height = 5.88 - 1.45;
  for (const double distance : {20.0, 30.0, 100.0}) {
    const auto with = testing::trace_linear(dir, "halo", halo_scene(distance, 0.5), options);
    const auto without = testing::trace_linear(dir, "no_halo", halo_scene(distance, 0.0), options);
    ASSERT_EQ(with.size(), 3u * kHalo * kHalo);
    ASSERT_EQ(without.size(), with.size());
    // The camera's basis: POV-Ray's look_at, right = y × direction, up = direction × right.
    const double range = std::hypot(distance, lens_height);
    const double dir_y = lens_height / range, dir_z = distance / range;
    const double up_y = dir_z, up_z = -dir_y;
    const double half = std::tan(5.0 * M_PI / 180.0);
    // Haze 0.01 (no fog declared), lamp power 22, share 0.5: σ_d · 2L = 0.22; cos θ_n.
    const double strength = 0.01 * 2 * 22 * 0.5 * lens_height / range;
    const int row = kHalo / 2 - 3;  // just above the lens: the cone below it is not drawn there
    for (const int column : {kHalo / 2 + 10, kHalo / 2 + 20, kHalo / 2 + 40}) {
      const double u = ((column + 0.5) / kHalo - 0.5) * 2 * half;
      const double v = (0.5 - (row + 0.5) / kHalo) * 2 * half;
      // The ray from the camera (at the origin here) to the sheet z = distance + 0.25.
      const double ray_x = u, ray_y = dir_y + v * up_y, ray_z = dir_z + v * up_z;
      const double t = (distance + 0.25) / ray_z;
      const double x = t * ray_x, y = t * ray_y - lens_height;
      const double rho = std::sqrt(x * x + y * y + 0.0025);
      const double expected = strength * lobe(rho / range) / rho;
      const std::size_t i = 3 * (static_cast<std::size_t>(row) * kHalo + column);
      const double measured = with[i] - without[i];
      std::printf("lamp %.0f m away, %.2f° beside it: halo %.4f, expected %.4f\n", distance,
                  std::atan(rho / range) * 180 / M_PI, measured, expected);
      EXPECT_NEAR(measured / expected, 1.0, 0.05) << "at " << distance << " m, column " << column;
    }
  }
  fs::remove_all(dir);
}

// A camera 1.45 m up, 30 m before a lens 5.88 m up, looking at it; the mist's drift held even;
// `knobs` declared before the template.
std::string lobes_scene(const std::string& knobs) {
  return "#version 3.7;\n"
         "global_settings { assumed_gamma 1 }\n"
         "#declare RT_CameraPosition = <0, 1.45, -30>;\n"
         "#declare RT_LightsOnly = 1;\n" +
         knobs +
         "#include \"night_street.inc\"\n"
         "#undef RT_MistDrift\n"
         "#declare RT_MistDrift = function { 0.5 }\n"
         "camera { perspective location RT_CameraPosition look_at <0, 5.88, 0> right x up y "
         "angle 20 }\n"
         "RT_LampGlow(<0, 5.88, 0>, <1, 1, 1>)\n";
}

// Where lobes_scene's glow is measured (20° over 64 pixels at 30.3 m: 0.167 m a pixel), in
// rows and columns from the lens: below it, rows 3–7; beside it, level with it, 0.5–1.2 m to
// the right.
struct Region {
  const char* name;
  int row0, row1, column0, column1;
};
constexpr Region kLobeRegions[] = {{"below", 3, 7, -2, 2}, {"beside", -1, 1, 3, 7}};

// Media fog scatters the lamps' light to the side itself, in the cones below them, and declares
// RT_LampCones = 0: the glow is then the forward lobes alone. The sheet's light is the cones'
// plus the lobes', so the glow without cones and the glow without lobes add up to the whole,
// below the lens (0.5–1.2 m down, clear of the clip at the lens) and beside it; and with neither
// nothing is drawn.
TEST(PovRayLampGlow, WithoutItsConesTheGlowIsTheMistsForwardLobesAlone) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_lamp_lobes");
  const std::string options = testing::square_size(kGlowSize) + " -A";
  const std::string no_lobes = "#declare RT_AureoleShare = 0;\n#declare RT_DiffractionShare = 0;\n";
  const std::string no_cones = "#declare RT_LampCones = 0;\n";
  const auto render = [&](const std::string& name, const std::string& knobs) {
    return testing::trace_linear(dir, name, lobes_scene(knobs), options);
  };
  const auto background = render("background", "#declare RT_LampHaze = 0;\n");
  const auto whole = render("whole", "");
  const auto lobes = render("lobes", no_cones);
  const auto cones = render("cones", no_lobes);
  const auto nothing = render("nothing", no_cones + no_lobes);
  ASSERT_EQ(background.size(), 3u * kGlowSize * kGlowSize);
  for (const auto* image : {&whole, &lobes, &cones, &nothing}) {
    ASSERT_EQ(image->size(), background.size());
  }
  for (const Region& r : kLobeRegions) {
    const double w = glow_over(whole, background, r.row0, r.row1, r.column0, r.column1);
    const double l = glow_over(lobes, background, r.row0, r.row1, r.column0, r.column1);
    const double c = glow_over(cones, background, r.row0, r.row1, r.column0, r.column1);
    const double n = glow_over(nothing, background, r.row0, r.row1, r.column0, r.column1);
    std::printf("%s the lens: whole %.5f, lobes %.5f + cones %.5f, neither %.6f\n", r.name, w, l, c,
                n);
    EXPECT_GT(l, 0.1 * w) << r.name << ": no forward lobes without the cones";
    EXPECT_GT(c, 0.1 * w) << r.name << ": no cones without the lobes";
    EXPECT_NEAR((l + c) / w, 1.0, 0.02) << r.name;
    EXPECT_LT(std::abs(n), 0.001 * w) << r.name;
  }
  fs::remove_all(dir);
}

// The street's lamps (RT_LightsOnly: their light sources alone) and a slab of scattering media,
// 1.5 m thick, in the air under the first lamp (its lens at x = 2.6, 5.93 m up, z = 5), seen
// from across the street; `knobs` declared before the template, `media` whether the slab is
// there. The slab scatters without extinction, so whatever it adds is light it scatters.
std::string lit_air_scene(const std::string& knobs, bool media) {
  return "#version 3.7;\n"
         "global_settings { assumed_gamma 1 }\n"
         "#declare RT_CameraPosition = <-6, 3, 5>;\n"
         "#declare RT_LightsOnly = 1;\n" +
         knobs +
         "#include \"night_street.inc\"\n"
         "camera { perspective location RT_CameraPosition look_at <2.6, 3, 5> angle 30 }\n" +
         (media ? "box { <1.85, 0.5, 3>, <3.35, 5, 7> hollow pigment { rgbt 1 }\n"
                  "  interior { media { scattering { 1, 0.05 extinction 0 } samples 4 } } }\n"
                : "");
}

// Where the glows draw a lamp's light in the air (RT_LampCones 1, the default), the lamps light
// no media: the rain medium's single sample a ray lit blotches wherever its midpoint passed a
// lamp, and its shadow rays cost a fifth of the default's final frame. Where media fog draws
// the cones (RT_LampCones 0), the lamps light it.
TEST(PovRayLampGlow, TheLampsLightMediaOnlyWhereTheGlowsDrawNoCones) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_lamp_media");
  const std::string options = testing::square_size(kGlowSize) + " -A";
  const std::string no_cones = "#declare RT_LampCones = 0;\n";
  const auto render = [&](const std::string& name, const std::string& knobs, bool media) {
    return testing::trace_linear(dir, name, lit_air_scene(knobs, media), options);
  };
  const auto glowing_air = render("glowing_air", "", false);
  const auto glowing_media = render("glowing_media", "", true);
  const auto fog_air = render("fog_air", no_cones, false);
  const auto fog_media = render("fog_media", no_cones, true);
  for (const auto* image : {&glowing_air, &glowing_media, &fog_air, &fog_media}) {
    ASSERT_EQ(image->size(), 3u * kGlowSize * kGlowSize);
  }
  const int half = kGlowSize / 2;
  const double lit_by_fog = glow_over(fog_media, fog_air, -half, half - 1, -half, half - 1);
  const double lit_by_glows =
      glow_over(glowing_media, glowing_air, -half, half - 1, -half, half - 1);
  std::printf("media under a lamp: %.6f where fog draws the cones, %.8f where the glows do\n",
              lit_by_fog, lit_by_glows);
  EXPECT_GT(lit_by_fog, 1e-3) << "the lamps light no media fog";
  EXPECT_LT(std::abs(lit_by_glows), 1e-4 * lit_by_fog) << "the lamps light the media";
  fs::remove_all(dir);
}

// The rain beyond far_m (RT_RainExtinction) scatters the lamps' light as the mist's forward
// lobe does, so where the glows draw the lamps' light in the air, they draw the rain's as more
// of that lobe: σ_rain / RT_LampHaze of the aureole. With the diffraction peak left out, the
// glow in rain of 0.004 /m and mist of 0.01 /m, aureole share 0.5, is the glow without rain at
// aureole share 0.9, below the lens and beside it; without cones (media fog lights the rain
// itself) the rain adds nothing.
TEST(PovRayLampGlow, TheRainBeyondFarMAddsItsScatteringToTheForwardLobe) {
  SKIP_WITHOUT_POVRAY();
  const fs::path dir = testing::folder_with_street("povray_test_lamp_rain");
  const std::string options = testing::square_size(kGlowSize) + " -A";
  const std::string mist = "#declare RT_LampHaze = 0.01;\n#declare RT_DiffractionShare = 0;\n";
  const std::string rain = "#declare RT_RainExtinction = 0.004;\n";
  const std::string no_cones = "#declare RT_LampCones = 0;\n";
  const auto render = [&](const std::string& name, const std::string& knobs) {
    return testing::trace_linear(dir, name, lobes_scene(knobs), options);
  };
  const auto background = render("background", "#declare RT_LampHaze = 0;\n");
  const auto dry = render("dry", mist);
  const auto wet = render("wet", mist + rain);
  const auto wider_lobe = render("wider_lobe", mist + "#declare RT_AureoleShare = 0.9;\n");
  const auto dry_lobes = render("dry_lobes", mist + no_cones);
  const auto wet_lobes = render("wet_lobes", mist + rain + no_cones);
  for (const auto* image : {&dry, &wet, &wider_lobe, &dry_lobes, &wet_lobes}) {
    ASSERT_EQ(image->size(), background.size());
  }
  for (const Region& r : kLobeRegions) {
    const auto glow = [&](const std::vector<float>& image) {
      return glow_over(image, background, r.row0, r.row1, r.column0, r.column1);
    };
    std::printf("%s the lens: dry %.5f, wet %.5f, aureole 0.9 %.5f; without cones %.5f, %.5f\n",
                r.name, glow(dry), glow(wet), glow(wider_lobe), glow(dry_lobes), glow(wet_lobes));
    EXPECT_GT(glow(wet), 1.05 * glow(dry)) << r.name << ": the rain adds no light";
    EXPECT_NEAR(glow(wet) / glow(wider_lobe), 1.0, 0.01) << r.name;
    EXPECT_NEAR(glow(wet_lobes) / glow(dry_lobes), 1.0, 0.001) << r.name;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace raintrace::povgen
