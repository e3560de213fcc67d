// What the exporter needs beyond the simulated frame: image, look, fog, environment.
// cli/ fills it from the scene file; names arriving here are already validated by cli/ AND
// re-checked by povgen before they touch POV-Ray text (defence in depth).
#pragma once

#include <glm/vec3.hpp>
#include <string>

#include "sim/camera.h"

namespace raintrace::povgen {

enum class FogMode {
  off,     ///< no fog (paper Fig. 2)
  ground,  ///< POV-Ray ground fog (fog_type 2): cheap
  media,   ///< scattering + absorbing media in a container (paper Fig. 3/4): Lambert-Beer
};

struct FogParams {
  /// Default off.
  FogMode mode = FogMode::off;
  /// Media: thickness of the foggy slab beyond the camera, metres, in (0, 1000]. Ground fog:
  /// the height it rises to. Default 20.
  double depth_m = 20.0;
  /// Extinction per metre (scattering + absorption), 1/m, in [0, 5]. Default 0.03.
  double density_per_m = 0.03;
  /// Linear RGB colour of the fog, each in [0, 1]. Default (0.6, 0.65, 0.7).
  glm::dvec3 colour{0.6, 0.65, 0.7};
};

struct EnvironmentParams {
  /// Built-in environment from templates/: "night_street", "field" or "closeup".
  /// Default "night_street".
  std::string name = "night_street";
  /// A user's own POV-Ray include instead of a built-in, path relative to the scene file's
  /// folder and inside it; empty = use `name`. Default empty.
  std::string include_path;
};

enum class Quality {
  /// No antialiasing, and scene.inc declares RT_Preview=1 so environments use cheaper
  /// stand-ins (night_street: light sheets for media cones, no granite normal, no window
  /// reflections): quick looks, tests and the throughput benchmark.
  preview,
  final,  ///< adaptive antialiasing (method 1, no jitter), RT_Preview=0: the full scene

};

struct ExportParams {
  sim::Camera camera;
  /// Diameter of the lens opening, metres, in [0, 1]. 0 (the default) is a pinhole: everything
  /// sharp. Otherwise the camera focuses on camera.look_at and blurs the rest (POV-Ray focal
  /// blur): a point at distance d, the focus at f, spreads over a disc of aperture_m·|d − f|/d
  /// at the plane of focus.
  double aperture_m = 0.0;
  /// Image size in pixels, each in [16, 8192]. Default 640×360.
  int width = 640;
  int height = 360;
  /// Frames per second of the animation, in (0, 240]. Default 24.
  double fps = 24.0;
  Quality quality = Quality::preview;
  /// Drops nearer than this are refractive spheres, farther ones streak quads, metres, >= 0.
  /// Default 3.
  double sphere_distance_m = 3.0;
  /// Level of detail for far rain, as a share of one pixel, in [0, 1]. A streak's coverage is
  /// the share of a pixel's light its drop would block: opacity × drop width / pixel width
  /// (× length / pixel when shorter than a pixel). A streak below this coverage adds a barely
  /// measurable tint to its pixels yet costs POV-Ray a ray hit per pixel it crosses, so it is
  /// kept with probability coverage / min_streak_coverage (keyed by the drop's id: the same
  /// drops stay from frame to frame) and drawn at min_streak_coverage: the expected light of
  /// the far field is unchanged, carried by fewer, brighter streaks. 0 keeps every streak.
  /// Default 1: every streak fainter than a full pixel is thinned (the heavy-rain example
  /// halves its streaks against 0.5 and its mean brightness moves by under 0.3/255).
  double min_streak_coverage = 1.0;
  /// Level of detail for splashes: the share of splash droplets written, in (0, 1]. Each
  /// droplet is kept or dropped by a key made of what stays constant over its flight (its
  /// horizontal velocity and size), so a droplet never blinks in and out; the survivors are
  /// drawn 1/√splash_keep wider, which keeps the total area the splashes cover. Droplets are
  /// glints of a few pixels that cost POV-Ray a sphere each (heavy rain throws ~30 k per
  /// frame). 1 writes every droplet. Default 0.5.
  double splash_keep = 0.5;
  /// At quality preview, let frames draw the environment plate: a picture of the environment
  /// without rain, rendered once (plate.ini → textures/environment_plate.png), placed behind the
  /// rain instead of ray tracing the environment in every frame. Only the environment's lights
  /// stay in the frame to light the rain. Applies to night_street and field without fog
  /// (environment_plate_applies()); frames with lightning trace the full environment. What it
  /// leaves out: the rain's reflection in the wet street, and scenery in front of rain that lies
  /// behind it (none within ~7 m of night_street's default camera). Default true.
  bool environment_plate = true;
  /// Also write a rain mask scene per frame (rain white on black). Default false.
  bool mask = false;
  FogParams fog;
  EnvironmentParams environment;
  /// Intensity of the lightning light at full flash, relative to the environment's key light,
  /// in [0, 100]. Default 8.
  double lightning_light = 8.0;
};

}  // namespace raintrace::povgen
