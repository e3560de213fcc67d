// Part (a) of scene generation: a simulated frame → the exact values the POV-Ray text will
// hold. Pure; culls to the view frustum, splits near, still drops (refractive spheres) from
// moving or far ones (streak quads) and builds each streak's camera-facing quad and atlas cell.
#pragma once

#include <array>
#include <glm/vec3.hpp>
#include <vector>

#include "povgen/export_params.h"
#include "povgen/ground_maps.h"
#include "povgen/streak_atlas.h"
#include "sim/frame.h"

namespace raintrace::povgen {

struct SphereValue {
  glm::vec3 centre;         ///< m
  float radius;             ///< m, equatorial (horizontal) radius
  float axis_ratio = 1.0f;  ///< vertical/horizontal; 1 = round, written without a scale
};

/// A camera-facing quad around a drop's velocity axis. Corners in order: start−side,
/// start+side, end+side, end−side (start = the drop's trailing end at shutter open).
struct StreakValue {
  std::array<glm::vec3, 4> corners;
  int cell;  ///< index into the streak atlas (streak_atlas_cell)
};

/// One straight piece of a lightning channel.
struct CylinderValue {
  glm::vec3 start;
  glm::vec3 end;
  float radius;  ///< the channel's (its glow reaches a multiple of it)
  /// The channel as drawn: at least half a pixel, so that POV-Ray without antialiasing does not
  /// miss a branch thinner than a pixel; its light is scaled by radius / core_radius, so the
  /// line carries the same light as the thin channel would.
  float core_radius;
};

/// The trunk radius that RT_BoltCore's emission (scene.inc) is set for: a trunk this thick at
/// brightness 1 sends the camera a return stroke's light per metre of channel
/// (scene_files.cpp, bolt_macros_text). A bolt drawn with any other trunk radius keeps that light
/// per metre (frame_text.cpp), so `[lightning] trunk_radius_m` sets how wide it is drawn only.
inline constexpr float kBoltLightTrunkRadius_m = 0.6f;

/// The segments of one bolt that glow alike: its main channel, or its branches of one
/// generation.
struct BoltValue {
  std::vector<CylinderValue> segments;
  float brightness;  ///< ~0..1: 1 is the first return stroke's peak in the main channel
  /// m: the radius of its bolt's trunk (generation 0), for every generation's group.
  float trunk_radius = kBoltLightTrunkRadius_m;
};

struct FrameValues {
  int index = 0;
  std::vector<SphereValue> drops;    ///< near drops (then near splash droplets)
  std::vector<StreakValue> streaks;  ///< far drops (then far splash droplets)
  std::vector<BoltValue> bolts;
  /// The frame's rings and the film's stir as the camera sees them (empty without puddles,
  /// and in frames that draw the environment plate): written beside the frame as
  /// ripples/ripple_NNNN.png (ground_scene.h).
  RippleMap ripples;
  /// Wet ground drawn (ground_scene.h's ground_applies): the frame declares its time for it.
  bool ground = false;
  double time_s = 0.0;  ///< simulated time of the frame
  /// Where each pixel sees the ground: kept from frame to frame (same camera, same pixels).
  GroundPixels ground_pixels;
  float flash = 0.0f;              ///< 0..1
  glm::vec3 flash_position{0.0f};  ///< where the lightning light sits
};

/// look.min_streak_coverage, or when it is not set (< 0) kPreviewStreakCoverage at preview and
/// kFinalStreakCoverage at final.
double streak_coverage_threshold(const ExportParams& look);

/// Builds the values of one frame. Drops nearer than look.sphere_distance_m that are at least
/// one pixel across, move less than their own height during the exposure and (with
/// focal_blur = rain) are out of focus by less than a pixel become spheres (stretched over
/// their path), all others streaks whose opacity is the share of the exposure the drop covers
/// each point (sim/streak.h). With focal_blur = rain a streak is built for its drop widened by
/// the lens's blur disc at its depth, aperture_m·|d − f|/f (f: look_at's depth), its opacity
/// scaled by the drop's outline over the widened one (same light). Splash droplets follow, the same
/// way (look.splash_keep of them, by id, carrying the others' light). Drops and droplets wholly
/// outside the view are dropped; a streak narrower (or shorter) than one pixel is drawn a pixel
/// wide and fainter by the same factor (its coverage of the pixel). Streaks fainter than
/// streak_coverage_threshold() are thinned out by drop id and the survivors drawn at that
/// coverage (same expected light, fewer quads). Throws
/// std::invalid_argument if the camera is degenerate or a value is not finite.
/// `threads` > 1 builds chunks of drops in parallel; the values are identical for every
/// thread count.
FrameValues build_frame_values(const sim::Frame& frame, const ExportParams& look,
                               const StreakAtlasLayout& atlas = {}, int threads = 1);

/// Same, into `values`, reusing its vectors' memory: a sequence of million-drop frames then
/// stops paying for fresh pages every frame.
void build_frame_values(const sim::Frame& frame, const ExportParams& look, FrameValues& values,
                        const StreakAtlasLayout& atlas = {}, int threads = 1);

}  // namespace raintrace::povgen
