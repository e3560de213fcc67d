// Tests for load_scene_string / load_scene_file: every key reaches its field, absent keys keep
// the params structs' defaults, and each kind of mistake is reported at its exact line:column.
#include <gtest/gtest.h>
#include <filesystem>
#include <fstream>

#include "cli/scene.h"
#include "tests/support/command.h"

namespace raintrace::cli {
namespace {

Scene load(std::string_view text) { return load_scene_string(text, "t.toml", "."); }

/// The one-line message of loading `text`, or "" when it loads.
std::string error_of(std::string_view text) {
  try {
    load(text);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(LoadScene, EmptyFileGivesTheStructDefaults) {
  const Scene scene = load("");
  const sim::SimParams sim;
  const povgen::ExportParams look;
  EXPECT_EQ(scene.frames, Scene{}.frames);
  EXPECT_EQ(scene.sim.seed, sim.seed);
  EXPECT_EQ(scene.sim.camera.position, sim.camera.position);
  EXPECT_EQ(scene.sim.camera.look_at, sim.camera.look_at);
  EXPECT_EQ(scene.sim.camera.fov_deg, sim.camera.fov_deg);
  EXPECT_EQ(scene.sim.camera.exposure_s, sim.camera.exposure_s);
  // 640/360 and 16/9 are the same rational, so the same correctly rounded double.
  EXPECT_EQ(scene.sim.camera.aspect, sim.camera.aspect);
  EXPECT_EQ(scene.sim.rain.rate_mm_per_h, sim.rain.rate_mm_per_h);
  EXPECT_EQ(scene.sim.rain.distribution, sim.rain.distribution);
  EXPECT_EQ(scene.sim.rain.diameter_min_mm, sim.rain.diameter_min_mm);
  EXPECT_EQ(scene.sim.rain.diameter_max_mm, sim.rain.diameter_max_mm);
  EXPECT_EQ(scene.sim.rain.near_m, sim.rain.near_m);
  EXPECT_EQ(scene.sim.rain.far_m, sim.rain.far_m);
  EXPECT_EQ(scene.sim.rain.ceiling_margin_m, sim.rain.ceiling_margin_m);
  EXPECT_EQ(scene.sim.rain.merging, sim.rain.merging);
  EXPECT_EQ(scene.sim.rain.breakup_diameter_mm, sim.rain.breakup_diameter_mm);
  EXPECT_EQ(scene.sim.rain.vanishing_rate_per_s, sim.rain.vanishing_rate_per_s);
  EXPECT_EQ(scene.sim.rain.colour, sim.rain.colour);
  EXPECT_EQ(scene.sim.wind.velocity_m_per_s, sim.wind.velocity_m_per_s);
  EXPECT_EQ(scene.sim.wind.gusts, sim.wind.gusts);
  EXPECT_EQ(scene.sim.wind.gust_strength, sim.wind.gust_strength);
  EXPECT_EQ(scene.sim.wind.gust_direction, sim.wind.gust_direction);
  EXPECT_EQ(scene.sim.wind.turbulence_m_per_s, sim.wind.turbulence_m_per_s);
  EXPECT_EQ(scene.sim.wind.turbulence_scale_m, sim.wind.turbulence_scale_m);
  EXPECT_EQ(scene.sim.splashes.enabled, sim.splashes.enabled);
  EXPECT_EQ(scene.sim.splashes.droplets, sim.splashes.droplets);
  EXPECT_EQ(scene.sim.splashes.lifetime_s, sim.splashes.lifetime_s);
  EXPECT_EQ(scene.sim.lightning.enabled, sim.lightning.enabled);
  EXPECT_EQ(scene.sim.lightning.strikes_per_minute, sim.lightning.strikes_per_minute);
  EXPECT_EQ(scene.sim.lightning.generations, sim.lightning.generations);
  EXPECT_EQ(scene.sim.lightning.cloud_height_m, sim.lightning.cloud_height_m);
  EXPECT_EQ(scene.sim.lightning.azimuth_deg, sim.lightning.azimuth_deg);
  EXPECT_EQ(scene.sim.lightning.azimuth_spread_deg, sim.lightning.azimuth_spread_deg);
  EXPECT_EQ(scene.sim.lightning.distance_m, sim.lightning.distance_m);
  EXPECT_EQ(scene.sim.lightning.distance_min_m, sim.lightning.distance_min_m);
  EXPECT_EQ(scene.sim.lightning.distance_max_m, sim.lightning.distance_max_m);
  EXPECT_EQ(scene.sim.lightning.trunk_radius_m, sim.lightning.trunk_radius_m);
  EXPECT_EQ(scene.sim.lightning.return_strokes, sim.lightning.return_strokes);
  EXPECT_EQ(scene.sim.lightning.flash_duration_s, sim.lightning.flash_duration_s);
  EXPECT_EQ(scene.sim.lightning.first_strike_s, sim.lightning.first_strike_s);
  EXPECT_EQ(scene.sim.ground_y_m, sim.ground_y_m);
  EXPECT_EQ(scene.sim.substep_s, sim.substep_s);
  EXPECT_EQ(scene.sim.prewarm_s, sim.prewarm_s);
  EXPECT_EQ(scene.look.width, look.width);
  EXPECT_EQ(scene.look.height, look.height);
  EXPECT_EQ(scene.look.fps, look.fps);
  EXPECT_EQ(scene.look.quality, look.quality);
  EXPECT_EQ(scene.look.sphere_distance_m, look.sphere_distance_m);
  EXPECT_EQ(scene.look.min_streak_coverage, look.min_streak_coverage);
  EXPECT_EQ(scene.look.mask, look.mask);
  EXPECT_EQ(scene.look.fog.mode, look.fog.mode);
  EXPECT_EQ(scene.look.fog.depth_m, look.fog.depth_m);
  EXPECT_EQ(scene.look.fog.density_per_m, look.fog.density_per_m);
  EXPECT_EQ(scene.look.fog.colour, look.fog.colour);
  EXPECT_EQ(scene.look.environment.name, look.environment.name);
  EXPECT_EQ(scene.look.environment.include_path, look.environment.include_path);
  EXPECT_EQ(scene.look.lightning_light, look.lightning_light);
}

TEST(LoadScene, EveryKeyReachesItsField) {
  const Scene scene = load(R"(
seed = 99
[output]
frames = 12
fps = 30
width = 320
height = 240
quality = "final"
[camera]
position = [1, 2, -3]
look_at = [0, 1, 4]
fov_deg = 45
exposure_s = 0.1
[rain]
rate_mm_per_h = 25.5
distribution = "uniform"
diameter_min_mm = 0.6
diameter_max_mm = 1.4
near_m = 0.5
far_m = 20
ceiling_margin_m = 3
merging = false
breakup_diameter_mm = 5
vanishing_rate_per_s = 0.5
colour = [0.5, 0.6, 0.7]
[wind]
velocity_m_per_s = [2, 0, -1]
gusts = true
gust_strength = 30
gust_direction = [3, 7, 4]
turbulence_m_per_s = 1.5
turbulence_scale_m = 8
[splashes]
enabled = false
droplets = 6
lifetime_s = 0.3
[lightning]
enabled = true
strikes_per_minute = 12
generations = 4
cloud_height_m = 500
azimuth_deg = -12.5
azimuth_spread_deg = 40
distance_m = 650
distance_min_m = 100
distance_max_m = 200
trunk_radius_m = 0.8
return_strokes = 2
flash_duration_s = 0.5
first_strike_s = 0.25
light = 20
[fog]
mode = "media"
depth_m = 40
density_per_m = 0.1
colour = [0.1, 0.2, 0.3]
[environment]
name = "field"
[export]
sphere_distance_m = 2.5
min_streak_coverage = 0.125
splash_keep = 0.75
environment_plate = false
mask = true
[simulation]
substep_s = 0.001
prewarm_s = 4
ground_y_m = -0.5
)");
  EXPECT_EQ(scene.sim.seed, 99u);
  EXPECT_EQ(scene.frames, 12);
  EXPECT_EQ(scene.look.fps, 30.0);
  EXPECT_EQ(scene.look.width, 320);
  EXPECT_EQ(scene.look.height, 240);
  EXPECT_EQ(scene.look.quality, povgen::Quality::final);
  EXPECT_EQ(scene.sim.camera.position, glm::dvec3(1, 2, -3));
  EXPECT_EQ(scene.sim.camera.look_at, glm::dvec3(0, 1, 4));
  EXPECT_EQ(scene.sim.camera.fov_deg, 45.0);
  EXPECT_EQ(scene.sim.camera.exposure_s, 0.1);
  EXPECT_EQ(scene.sim.camera.aspect, 320.0 / 240.0);
  // The camera goes to both consumers unchanged.
  EXPECT_EQ(scene.look.camera.position, scene.sim.camera.position);
  EXPECT_EQ(scene.look.camera.look_at, scene.sim.camera.look_at);
  EXPECT_EQ(scene.look.camera.fov_deg, scene.sim.camera.fov_deg);
  EXPECT_EQ(scene.look.camera.exposure_s, scene.sim.camera.exposure_s);
  EXPECT_EQ(scene.look.camera.aspect, scene.sim.camera.aspect);
  EXPECT_EQ(scene.sim.rain.rate_mm_per_h, 25.5);
  EXPECT_EQ(scene.sim.rain.distribution, sim::DropSizeDistribution::uniform);
  EXPECT_EQ(scene.sim.rain.diameter_min_mm, 0.6);
  EXPECT_EQ(scene.sim.rain.diameter_max_mm, 1.4);
  EXPECT_EQ(scene.sim.rain.near_m, 0.5);
  EXPECT_EQ(scene.sim.rain.far_m, 20.0);
  EXPECT_EQ(scene.sim.rain.ceiling_margin_m, 3.0);
  EXPECT_FALSE(scene.sim.rain.merging);
  EXPECT_EQ(scene.sim.rain.breakup_diameter_mm, 5.0);
  EXPECT_EQ(scene.sim.rain.vanishing_rate_per_s, 0.5);
  EXPECT_EQ(scene.sim.rain.colour, glm::dvec3(0.5, 0.6, 0.7));
  EXPECT_EQ(scene.sim.wind.velocity_m_per_s, glm::dvec3(2, 0, -1));
  EXPECT_TRUE(scene.sim.wind.gusts);
  EXPECT_EQ(scene.sim.wind.gust_strength, 30.0);
  // [3, 7, 4]: y dropped, (3, 4) has length 5, so the unit direction is (0.6, 0, 0.8).
  EXPECT_DOUBLE_EQ(scene.sim.wind.gust_direction.x, 0.6);
  EXPECT_EQ(scene.sim.wind.gust_direction.y, 0.0);
  EXPECT_DOUBLE_EQ(scene.sim.wind.gust_direction.z, 0.8);
  EXPECT_EQ(scene.sim.wind.turbulence_m_per_s, 1.5);
  EXPECT_EQ(scene.sim.wind.turbulence_scale_m, 8.0);
  EXPECT_FALSE(scene.sim.splashes.enabled);
  EXPECT_EQ(scene.sim.splashes.droplets, 6);
  EXPECT_EQ(scene.sim.splashes.lifetime_s, 0.3);
  EXPECT_TRUE(scene.sim.lightning.enabled);
  EXPECT_EQ(scene.sim.lightning.strikes_per_minute, 12.0);
  EXPECT_EQ(scene.sim.lightning.generations, 4);
  EXPECT_EQ(scene.sim.lightning.cloud_height_m, 500.0);
  EXPECT_EQ(scene.sim.lightning.azimuth_deg, -12.5);
  EXPECT_EQ(scene.sim.lightning.azimuth_spread_deg, 40.0);
  EXPECT_EQ(scene.sim.lightning.distance_m, 650.0);
  EXPECT_EQ(scene.sim.lightning.distance_min_m, 100.0);
  EXPECT_EQ(scene.sim.lightning.distance_max_m, 200.0);
  EXPECT_EQ(scene.sim.lightning.trunk_radius_m, 0.8);
  EXPECT_EQ(scene.sim.lightning.return_strokes, 2);
  EXPECT_EQ(scene.sim.lightning.flash_duration_s, 0.5);
  EXPECT_EQ(scene.sim.lightning.first_strike_s, 0.25);
  EXPECT_EQ(scene.look.lightning_light, 20.0);
  EXPECT_EQ(scene.look.fog.mode, povgen::FogMode::media);
  EXPECT_EQ(scene.look.fog.depth_m, 40.0);
  EXPECT_EQ(scene.look.fog.density_per_m, 0.1);
  EXPECT_EQ(scene.look.fog.colour, glm::dvec3(0.1, 0.2, 0.3));
  EXPECT_EQ(scene.look.environment.name, "field");
  EXPECT_EQ(scene.look.sphere_distance_m, 2.5);
  EXPECT_EQ(scene.look.min_streak_coverage, 0.125);
  EXPECT_EQ(scene.look.splash_keep, 0.75);
  EXPECT_FALSE(scene.look.environment_plate);
  EXPECT_TRUE(scene.look.mask);
  EXPECT_EQ(scene.sim.substep_s, 0.001);
  EXPECT_EQ(scene.sim.prewarm_s, 4.0);
  EXPECT_EQ(scene.sim.ground_y_m, -0.5);
}

TEST(LoadScene, KeepsTheTextAndTheSourceName) {
  const std::string text = "seed = 3\n";
  const Scene scene = load(text);
  EXPECT_EQ(scene.text, text);
  EXPECT_EQ(scene.source, "t.toml");
}

TEST(LoadScene, DottedKeysAndInlineTablesWorkLikeSections) {
  const Scene scene = load("rain.rate_mm_per_h = 10\nwind = { gusts = true }\n");
  EXPECT_EQ(scene.sim.rain.rate_mm_per_h, 10.0);
  EXPECT_TRUE(scene.sim.wind.gusts);
}

// Column numbers below count from 1 at the start of the line: in `rate_mm_per_h = -3` the
// value starts after 16 characters ("rate_mm_per_h = "), so at column 17.
TEST(SceneErrors, OutOfRangeNumber) {
  EXPECT_EQ(error_of("[rain]\nrate_mm_per_h = -3\n"),
            "t.toml:2:17: rain.rate_mm_per_h: must be in [0, 500], got -3");
  EXPECT_EQ(error_of("[output]\nfps = 0\n"), "t.toml:2:7: output.fps: must be in (0, 240], got 0");
  EXPECT_EQ(error_of("[output]\nwidth = 8193\n"),
            "t.toml:2:9: output.width: must be in [16, 8192], got 8193");
  EXPECT_EQ(error_of("[export]\nsphere_distance_m = -1.5\n"),
            "t.toml:2:21: export.sphere_distance_m: must be in [0, 1000], got -1.5");
  EXPECT_EQ(error_of("[export]\nmin_streak_coverage = 2\n"),
            "t.toml:2:23: export.min_streak_coverage: must be in [0, 1], got 2");
  EXPECT_EQ(error_of("[export]\nsplash_keep = 0\n"),
            "t.toml:2:15: export.splash_keep: must be in (0, 1], got 0");
}

TEST(SceneErrors, UnknownKeySuggestsTheClosest) {
  EXPECT_EQ(error_of("[rain]\nrate_mm_per_h = 5\nrate_mm_per_hr = 5\n"),
            "t.toml:3:1: rain.rate_mm_per_hr: unknown key (did you mean 'rate_mm_per_h'?)");
  EXPECT_EQ(error_of("[fog]\n  color = [1, 1, 1]\n"),
            "t.toml:2:3: fog.color: unknown key (did you mean 'colour'?)");
}

TEST(SceneErrors, UnknownSectionSuggestsTheClosest) {
  EXPECT_EQ(error_of("seed = 1\n[rian]\nrate_mm_per_h = 5\n"),
            "t.toml:2:2: rian: unknown section (did you mean 'rain'?)");
}

TEST(SceneErrors, UnknownTopLevelKey) {
  const std::string error = error_of("\nsed = 4\n");
  EXPECT_EQ(error, "t.toml:2:1: sed: unknown key (did you mean 'seed'?)");
}

TEST(SceneErrors, NestedTableInASectionIsAnUnknownKey) {
  EXPECT_EQ(
      error_of("[rain.extra]\nx = 1\n"),
      "t.toml:1:7: rain.extra: unknown key (known keys of [rain]: rate_mm_per_h, "
      "distribution, diameter_min_mm, diameter_max_mm, near_m, far_m, ceiling_margin_m, "
      "merging, breakup_diameter_mm, vanishing_rate_per_s, colour, lamp_reach_m, lamp_far_m)");
}

TEST(SceneErrors, WrongTypes) {
  EXPECT_EQ(error_of("[output]\nframes = \"48\"\n"),
            "t.toml:2:10: output.frames: expected an integer, got string \"48\"");
  EXPECT_EQ(error_of("[rain]\nmerging = \"yes\"\n"),
            "t.toml:2:11: rain.merging: expected true or false, got string \"yes\"");
  EXPECT_EQ(error_of("[rain]\nrate_mm_per_h = true\n"),
            "t.toml:2:17: rain.rate_mm_per_h: expected a number, got true");
  EXPECT_EQ(error_of("[environment]\ninclude = 3\n"),
            "t.toml:2:11: environment.include: expected a string, got 3");
  EXPECT_EQ(error_of("[lightning]\nfirst_strike_s = 1979-05-27\n"),
            "t.toml:2:18: lightning.first_strike_s: expected a number, got a date");
}

TEST(SceneErrors, FloatWhereAnIntegerIsExpected) {
  EXPECT_EQ(error_of("[output]\nframes = 48.0\n"),
            "t.toml:2:10: output.frames: expected an integer, got float 48");
  EXPECT_EQ(error_of("seed = 1.5\n"), "t.toml:1:8: seed: expected an integer, got float 1.5");
}

TEST(SceneErrors, IntegerWhereAFloatIsExpectedIsAccepted) {
  EXPECT_EQ(load("[output]\nfps = 30\n").look.fps, 30.0);
}

TEST(SceneErrors, NonFiniteNumbers) {
  EXPECT_EQ(error_of("[output]\nfps = inf\n"),
            "t.toml:2:7: output.fps: must be a finite number, got inf");
  EXPECT_EQ(error_of("[simulation]\nground_y_m = nan\n"),
            "t.toml:2:14: simulation.ground_y_m: must be a finite number, got nan");
  EXPECT_EQ(error_of("[camera]\nposition = [0, -inf, 0]\n"),
            "t.toml:2:16: camera.position[1]: must be a finite number, got -inf");
}

TEST(SceneErrors, BadEnumStrings) {
  EXPECT_EQ(error_of("[output]\nquality = \"best\"\n"),
            "t.toml:2:11: output.quality: expected one of \"preview\", \"final\", got string "
            "\"best\"");
  EXPECT_EQ(error_of("[rain]\ndistribution = \"marshal-palmer\"\n"),
            "t.toml:2:16: rain.distribution: expected one of \"marshall-palmer\", \"uniform\", "
            "got string \"marshal-palmer\" (did you mean \"marshall-palmer\"?)");
  EXPECT_EQ(error_of("[fog]\nmode = 1\n"),
            "t.toml:2:8: fog.mode: expected one of \"off\", \"ground\", \"media\", got 1");
  EXPECT_EQ(error_of("[environment]\nname = \"night-street\"\n"),
            "t.toml:2:8: environment.name: expected one of \"night_street\", \"field\", "
            "\"closeup\", got string \"night-street\" (did you mean \"night_street\"?)");
}

TEST(SceneErrors, ArraysOfTheWrongLengthOrContent) {
  EXPECT_EQ(error_of("[camera]\nposition = [1, 2]\n"),
            "t.toml:2:12: camera.position: expected an array of 3 numbers [x, y, z], got an "
            "array of 2 elements");
  EXPECT_EQ(error_of("[wind]\nvelocity_m_per_s = 3\n"),
            "t.toml:2:20: wind.velocity_m_per_s: expected an array of 3 numbers [x, y, z], got 3");
  EXPECT_EQ(error_of("[camera]\nposition = [1, \"a\", 3]\n"),
            "t.toml:2:16: camera.position[1]: expected a number, got string \"a\"");
  EXPECT_EQ(error_of("[rain]\ncolour = [1, 0.5, 1.5]\n"),
            "t.toml:2:19: rain.colour[2]: must be in [0, 1], got 1.5");
}

TEST(SceneErrors, CrossFieldRules) {
  EXPECT_EQ(error_of("[rain]\ndiameter_min_mm = 3\ndiameter_max_mm = 2\n"),
            "t.toml:3:19: rain.diameter_max_mm: rain.diameter_min_mm must be <= "
            "rain.diameter_max_mm, got 3 > 2");
  // Only the minimum given: it is compared with the default maximum (6) and blamed.
  EXPECT_EQ(error_of("[rain]\ndiameter_min_mm = 7\n"),
            "t.toml:2:19: rain.diameter_min_mm: rain.diameter_min_mm must be <= "
            "rain.diameter_max_mm, got 7 > 6");
  EXPECT_EQ(error_of("[rain]\nnear_m = 2\nfar_m = 2\n"),
            "t.toml:3:9: rain.far_m: rain.far_m must be > rain.near_m, got 2 <= 2");
  EXPECT_EQ(error_of("[camera]\nposition = [0, 1.6, 0]\n"),
            "t.toml:2:12: camera.position: must differ from camera.look_at (both are [0, 1.6, 0])");
  EXPECT_EQ(error_of("[camera]\nposition = [0, 1, 0]\nlook_at = [0, 1, 0]\n"),
            "t.toml:3:11: camera.look_at: must differ from camera.position (both are [0, 1, 0])");
  EXPECT_EQ(error_of("[camera]\nlook_at = [0, 10, -5]\n"),
            "t.toml:2:11: camera.look_at: must not lie straight above or below camera.position "
            "(the camera keeps +y up)");
  EXPECT_EQ(error_of("[lightning]\ndistance_min_m = 300\ndistance_max_m = 200\n"),
            "t.toml:3:18: lightning.distance_max_m: lightning.distance_min_m must be <= "
            "lightning.distance_max_m, got 300 > 200");
  EXPECT_EQ(error_of("[wind]\ngust_direction = [0, 1, 0]\n"),
            "t.toml:2:18: wind.gust_direction: must point somewhere horizontally (x or z not 0; "
            "y is ignored)");
  // A bladed iris: a polygon of three blades or more, and an opening for the spikes to come from.
  EXPECT_EQ(error_of("[camera]\naperture_m = 0.008\naperture_blades = 2\n"),
            "t.toml:3:19: camera.aperture_blades: must be 0 (a round opening) or 3 to 16 blades, "
            "got 2");
  EXPECT_EQ(error_of("[camera]\naperture_blades = 6\n"),
            "t.toml:2:19: camera.aperture_blades: needs camera.aperture_m > 0: the spikes' length "
            "comes from the opening's size");
  EXPECT_EQ(load("[camera]\naperture_m = 0.008\naperture_blades = 6\n").develop.aperture_blades, 6);
  // The lens barrel's rim clips a traced focal blur's rays: none without an opening, none when
  // only the rain is blurred.
  EXPECT_EQ(error_of("[camera]\noptical_vignetting = 0.5\n"),
            "t.toml:2:22: camera.optical_vignetting: needs a traced focal blur: camera.aperture_m "
            "> 0 and camera.focal_blur = \"traced\"");
  EXPECT_EQ(error_of("[camera]\naperture_m = 0.008\nfocal_blur = \"rain\"\n"
                     "optical_vignetting = 0.5\n"),
            "t.toml:4:22: camera.optical_vignetting: needs a traced focal blur: camera.aperture_m "
            "> 0 and camera.focal_blur = \"traced\"");
  EXPECT_EQ(error_of("[camera]\naperture_m = 0.008\noptical_vignetting = 1.5\n"),
            "t.toml:3:22: camera.optical_vignetting: must be in [0, 1], got 1.5");
  EXPECT_EQ(
      load("[camera]\naperture_m = 0.008\noptical_vignetting = 0.5\n").look.optical_vignetting,
      0.5);
  // A white balance: off, or a colour temperature the blackbody fit covers.
  EXPECT_EQ(error_of("[camera]\nwhite_balance_k = 1500\n"),
            "t.toml:2:19: camera.white_balance_k: must be 0 (off: D65 white, the colours as "
            "traced) or in [2000, 20000] K, got 1500");
  EXPECT_EQ(error_of("[camera]\nwhite_balance_k = 30000\n"),
            "t.toml:2:19: camera.white_balance_k: must be in [0, 20000], got 30000");
  EXPECT_EQ(load("[camera]\nwhite_balance_k = 3500\n").develop.white_balance_k, 3500);
}

TEST(SceneErrors, SectionThatIsNotATable) {
  EXPECT_EQ(error_of("rain = 5\n"), "t.toml:1:8: rain: expected a table (a [rain] section), got 5");
  EXPECT_EQ(error_of("[[rain]]\n"),
            "t.toml:1:1: rain: expected a table (a [rain] section), got an array of 1 element");
}

TEST(SceneErrors, SeedMustBeANonNegativeInteger) {
  EXPECT_EQ(error_of("seed = -1\n"), "t.toml:1:8: seed: must be >= 0, got -1");
  EXPECT_EQ(load("seed = 9223372036854775807\n").sim.seed, 9223372036854775807u);
}

TEST(SceneErrors, TomlSyntaxErrorsGetTheSameFormat) {
  const std::string error = error_of("[rain]\nrate_mm_per_h = = 5\n");
  EXPECT_EQ(error.rfind("t.toml:2:", 0), 0u) << error;
  EXPECT_NE(error.find(": syntax error: "), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  const std::string duplicate = error_of("seed = 1\nseed = 2\n");
  EXPECT_EQ(duplicate.rfind("t.toml:2:", 0), 0u) << duplicate;
}

TEST(SceneErrors, HostileKeysAndValuesStayOnOneLine) {
  for (const char* text : {"\"a\\nb\" = 1\n", "[rain]\n\"\\u001b[31m\" = 1\n",
                           "[output]\nquality = \"a\\nb\\u001b\"\n"}) {
    const std::string error = error_of(text);
    EXPECT_FALSE(error.empty()) << text;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    EXPECT_EQ(error.find('\x1b'), std::string::npos) << error;
  }
}

TEST(LoadSceneFile, MissingFileIsASceneError) {
  try {
    load_scene_file("does/not/exist.toml");
    FAIL() << "expected SceneError";
  } catch (const SceneError& e) {
    EXPECT_STREQ(e.what(), "does/not/exist.toml: cannot read the scene file: no such file");
  }
}

TEST(LoadSceneFile, ReadsTheFileAndResolvesIncludesBesideIt) {
  namespace fs = std::filesystem;
  const fs::path dir = raintrace::test_support::process_scratch_path("raintrace_scene_file_test");
  fs::create_directories(dir / "env");
  std::ofstream(dir / "env" / "street.inc") << "// user environment\n";
  std::ofstream(dir / "scene.toml") << "seed = 5\n[environment]\ninclude = \"env/street.inc\"\n";
  const Scene scene = load_scene_file(dir / "scene.toml");
  EXPECT_EQ(scene.sim.seed, 5u);
  EXPECT_EQ(scene.look.environment.include_path, "env/street.inc");
  EXPECT_TRUE(fs::equivalent(scene.base_dir, dir));
  EXPECT_EQ(scene.source, (dir / "scene.toml").string());
  fs::remove_all(dir);
}

// An output folder's identity (canonical_scene_text): the loaded values that shape a rendered
// frame and differ from the built-in defaults. A key a later raintrace adds, left at its default,
// must not make an old scene "another scene" and cost it its finished frames.
TEST(SceneIdentity, KeysAtTheirDefaultsAndDevelopKeysAddNothing) {
  const std::string plain = canonical_scene_text(load(""));
  EXPECT_EQ(plain.rfind("raintrace scene, canonical form 2\n", 0), 0u) << plain;
  EXPECT_EQ(canonical_scene_text(load("[camera]\noptical_vignetting = 0\n")), plain);
  EXPECT_EQ(canonical_scene_text(load("[rain]\nrate_mm_per_h = 5e0\n")),
            canonical_scene_text(load("[rain]\nrate_mm_per_h = 5\n")));
  EXPECT_EQ(canonical_scene_text(load("[camera]\nexposure_ev = -1\nvignette = 1\n")), plain);
  EXPECT_EQ(canonical_scene_text(load("seed = 7\n[output]\nwidth = 320\n")), plain);
  // A key away from its default is a line of its own, and another scene.
  const std::string open = canonical_scene_text(load("[camera]\naperture_m = 0.01\n"));
  EXPECT_NE(open, plain);
  EXPECT_NE(open.find("\ncamera.aperture_m=0.01\n"), std::string::npos) << open;
  EXPECT_EQ(plain.find("camera.aperture_m"), std::string::npos) << plain;
}

}  // namespace
}  // namespace raintrace::cli
