// What the exporter needs beyond the simulated frame: image, look, fog, environment. Below
// each struct, its parameter table (sim/param_table.h) gives every scene-file key its unit and
// valid range; defaults are the member initialisers. cli/ fills these from the scene file;
// values arriving here are already checked by cli/ AND re-checked by povgen (validate())
// before they touch POV-Ray text (defence in depth).
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <string_view>

#include "sim/camera.h"
#include "sim/param_table.h"
#include "sim/params.h"

namespace raintrace::povgen {

enum class FogMode {
  off,     ///< no fog (paper Fig. 2)
  ground,  ///< POV-Ray ground fog (fog_type 2): cheap
  media,   ///< scattering + absorbing media in a container (paper Fig. 3/4): Lambert-Beer
};
/// Scene-file names of FogMode, in the order of its values.
inline constexpr std::string_view kFogModeNames[] = {"off", "ground", "media"};

struct FogParams {
  FogMode mode = FogMode::off;
  /// Media: thickness of the foggy slab beyond the camera. Ground fog: the height it rises to.
  double depth_m = 20.0;
  /// Extinction per metre (scattering + absorption).
  double density_per_m = 0.03;
  /// Linear RGB colour of the fog.
  glm::dvec3 colour{0.6, 0.65, 0.7};
};

/// [fog]
inline constexpr sim::Param<FogParams> kFogParams[] = {
    sim::choice<&FogParams::mode>("fog", "mode", kFogModeNames),
    sim::number("fog", "depth_m", &FogParams::depth_m, "m", sim::Range::open_closed(0, 1000)),
    sim::number("fog", "density_per_m", &FogParams::density_per_m, "1/m", sim::Range::closed(0, 5)),
    sim::colour("fog", "colour", &FogParams::colour),
};
static_assert(sim::well_formed<FogParams>(kFogParams));

/// The built-in environments of templates/ (templates.h gives their text).
inline constexpr std::string_view kEnvironmentNames[] = {"night_street", "field", "closeup"};

struct EnvironmentParams {
  /// Built-in environment from templates/, one of kEnvironmentNames.
  std::string name = "night_street";
  /// A user's own POV-Ray include instead of a built-in, path relative to the scene file's
  /// folder and inside it; empty = use `name`. cli/scene_include.cpp checks it.
  std::string include_path;
};

/// [environment]
inline constexpr sim::Param<EnvironmentParams> kEnvironmentParams[] = {
    sim::choice<&EnvironmentParams::name>("environment", "name", kEnvironmentNames),
    sim::text("environment", "include", &EnvironmentParams::include_path)
        .with_note("see below")
        .unset_as("none"),
};
static_assert(sim::well_formed<EnvironmentParams>(kEnvironmentParams));

enum class Quality {
  /// No antialiasing, and scene.inc declares RT_Preview=1 so environments use cheaper
  /// stand-ins (night_street: light sheets for media cones, no granite normal, no window
  /// reflections): quick looks, tests and the throughput benchmark.
  preview,
  final,  ///< adaptive antialiasing (method 1, no jitter), RT_Preview=0: the full scene
};
/// Scene-file names of Quality, in the order of its values.
inline constexpr std::string_view kQualityNames[] = {"preview", "final"};
/// The scene-file name of a quality ("preview", "final").
inline constexpr std::string_view quality_name(Quality quality) {
  return kQualityNames[static_cast<std::size_t>(quality)];
}

/// How a lens opening (ExportParams::aperture_m) blurs the picture.
enum class FocalBlur {
  /// POV-Ray's focal blur over everything: up to 256 rays a pixel at quality final.
  traced,
  /// Only the rain, drawn out of focus: each drop's streak widened by its blur disc, its
  /// coverage spread over the wider outline (frame_values.h). The scenery stays sharp, and the
  /// frame costs what a pinhole's does: where the scenery lies far beyond the rain (a street
  /// focused tens of metres away), its own blur is a fraction of the near rain's.
  rain,
};
/// Scene-file names of FocalBlur, in the order of its values.
inline constexpr std::string_view kFocalBlurNames[] = {"traced", "rain"};

/// min_streak_coverage when a scene does not set it: the preview's and the final look's.
inline constexpr double kPreviewStreakCoverage = 0.01;
inline constexpr double kFinalStreakCoverage = 0.003;

/// The wet ground: povgen draws the simulation's puddles (the same field, sim/puddles.h) and the
/// ripples of each frame's impacts through templates/raintrace_ground.inc.
struct GroundLook {
  /// The scene's puddles, coverage resolved (<= 0: none, and the ground is drawn as before).
  sim::PuddleParams puddles;
  /// The scene's ripples: with the rain's rate (ExportParams::rain), the roughness the rings
  /// give a puddle where a pixel is too coarse to draw them (sim::ripple_slope_rms()).
  sim::RippleParams ripples;
  /// Height of the ground plane, m (the simulation's ground_y_m).
  double ground_y_m = 0.0;
};

struct ExportParams {
  sim::Camera camera;
  /// Diameter of the lens opening; 0 is a pinhole: everything sharp. Otherwise the camera
  /// focuses on camera.look_at and blurs the rest (POV-Ray focal blur): a point at distance d,
  /// the focus at f, spreads over a disc of aperture_m·|d − f|/d at the plane of focus.
  double aperture_m = 0.0;
  /// What aperture_m blurs: everything, traced by POV-Ray, or the rain alone, drawn blurred.
  FocalBlur focal_blur = FocalBlur::traced;
  /// The lens barrel's rim clipping the opening toward the corners (lens_barrel.h): the
  /// out-of-focus discs become cat's eyes, half of the opening cut at the corners, the cut
  /// starting (1 − optical_vignetting) of the way out from the centre. 0 = none. Needs a traced
  /// focal blur.
  double optical_vignetting = 0.0;
  /// The rain as simulated (cli/ copies it from the scene, like the camera): its drop sizes and
  /// rate give the rain medium beyond rain.far_m (rain_medium_text()).
  sim::RainParams rain;
  /// Continue the rain beyond rain.far_m as a participating medium whose extinction and
  /// scattering follow from the drops (docs/rain-appearance.md).
  bool rain_medium = true;
  /// Image size.
  int width = 640;
  int height = 360;
  /// Frames per second of the animation.
  double fps = 24.0;
  Quality quality = Quality::preview;
  /// Drops nearer than this are refractive spheres, farther ones streak quads.
  double sphere_distance_m = 3.0;
  /// Level of detail for streaks. A streak's coverage is the share of its pixels' light its
  /// drop replaces: the share of the exposure the drop spends on each point of the streak (its
  /// size / its travel, Garg & Nayar 2006) × its width / a pixel when narrower. A streak below
  /// this coverage adds a barely measurable tint to its pixels yet costs POV-Ray a ray hit per
  /// pixel it crosses, so it is kept with probability coverage / min_streak_coverage (keyed by
  /// the drop's id: the same drops stay from frame to frame) and drawn at min_streak_coverage:
  /// the expected light is unchanged, carried by fewer, brighter streaks. 0 keeps every streak
  /// (the atlas's floor, ~1.6e-4, is always applied the same way). Not set (−1): 0.003 at
  /// quality final — the picture keeps the fine veil of every streak at 45 % of its cost — and
  /// 0.01 at preview, a grainier veil at 20 % (docs/rain-appearance.md compares them).
  double min_streak_coverage = -1.0;
  /// Level of detail for splashes: the share of splash droplets written. Each
  /// droplet is kept or dropped by a key made of what stays constant over its flight (its
  /// horizontal velocity and size), so a droplet never blinks in and out; the survivors are
  /// drawn 1/√splash_keep wider, which keeps the total area the splashes cover. Droplets are
  /// glints of a few pixels that cost POV-Ray a sphere each (heavy rain throws ~30 k per
  /// frame). 1 writes every droplet.
  double splash_keep = 0.5;
  /// At quality preview, let frames draw the environment plate: a picture of the environment
  /// without rain, rendered once (plate.ini → textures/environment_plate.exr), placed behind the
  /// rain instead of ray tracing the environment in every frame. Only the environment's lights
  /// stay in the frame to light the rain. Applies to night_street and field without fog or in
  /// thin fog, which the plate then holds (environment_plate_applies()); frames with lightning
  /// trace the full environment. What it leaves out: the rain's reflection in the wet street,
  /// and scenery in front of rain that lies behind it (none within ~7 m of night_street's
  /// default camera).
  bool environment_plate = true;
  /// Also write a rain mask scene per frame (rain white on black).
  bool mask = false;
  FogParams fog;
  EnvironmentParams environment;
  /// Not scene keys of their own: cli fills it from [puddles], [ripples] and [rain].
  GroundLook ground;
  /// Intensity of the lightning light at full flash, relative to the environment's key light.
  double lightning_light = 8.0;
};

/// ExportParams' own keys, in four sections: [camera] aperture_m, focal_blur and
/// optical_vignetting, [output] (after cli's `frames`), [export] and [lightning] light. Its
/// camera is sim::kCameraParams, fog and environment their own tables.
inline constexpr sim::Param<ExportParams> kExportParams[] = {
    sim::number("camera", "aperture_m", &ExportParams::aperture_m, "m", sim::Range::closed(0, 1)),
    sim::choice<&ExportParams::focal_blur>("camera", "focal_blur", kFocalBlurNames),
    sim::number("camera", "optical_vignetting", &ExportParams::optical_vignetting, "share",
                sim::Range::closed(0, 1)),
    sim::number("output", "fps", &ExportParams::fps, "1/s", sim::Range::open_closed(0, 240)),
    sim::integer("output", "width", &ExportParams::width, "pixels", 16, 8192),
    sim::integer("output", "height", &ExportParams::height, "pixels", 16, 8192),
    sim::choice<&ExportParams::quality>("output", "quality", kQualityNames),
    sim::number("export", "sphere_distance_m", &ExportParams::sphere_distance_m, "m",
                sim::Range::closed(0, 1000)),
    sim::number("export", "min_streak_coverage", &ExportParams::min_streak_coverage, "coverage",
                sim::Range::closed(0, 1))
        .unset_as("automatic"),
    sim::number("export", "splash_keep", &ExportParams::splash_keep, "share",
                sim::Range::open_closed(0, 1)),
    sim::flag("export", "environment_plate", &ExportParams::environment_plate),
    sim::flag("export", "rain_medium", &ExportParams::rain_medium),
    sim::flag("export", "mask", &ExportParams::mask),
    sim::number("lightning", "light", &ExportParams::lightning_light, "",
                sim::Range::closed(0, 100)),
};
static_assert(sim::well_formed<ExportParams>(kExportParams));

/// POV-Ray traces the focal blur: a lens is open and focal_blur is traced.
inline bool traces_focal_blur(const ExportParams& look) {
  return look.aperture_m > 0.0 && look.focal_blur == FocalBlur::traced;
}

/// The lens blurs the rain alone: a lens is open and focal_blur is rain.
inline bool blurs_rain_only(const ExportParams& look) {
  return look.aperture_m > 0.0 && look.focal_blur == FocalBlur::rain;
}

/// Throws std::invalid_argument when optical_vignetting is set without a traced focal blur: the
/// lens barrel's rim clips the rays POV-Ray spreads over the opening, which a pinhole or a blur
/// of the rain alone does not trace.
void check_optical_vignetting(const ExportParams& look);

/// Throws std::invalid_argument naming the first field out of its range (the tables above and
/// sim::kCameraParams), or an environment that is not built in when no include is given.
void validate(const ExportParams& look);

}  // namespace raintrace::povgen
