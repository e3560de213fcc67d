// Frame → values: culling, near/far split, streak quads, lightning light placement.
#include "povgen/frame_values.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>

#include "povgen/drop_shape.h"
#include "povgen/ground_scene.h"
#include "povgen/ordered_chunks.h"
#include "povgen/scene_files.h"
#include "povgen/view_frustum.h"
#include "sim/lightning.h"
#include "sim/random.h"
#include "sim/streak.h"

namespace raintrace::povgen {
namespace {

/// Axis ratios below this are written with a scale; above it the flattening is under 0.5 % of
/// the radius, invisible at any size we render, and a bare sphere parses 40 % faster.
constexpr float kRoundEnough = 0.995f;

struct StreakContext {
  const ViewFrustum& view;
  const StreakAtlasLayout& atlas;
  float exposure_s;
  int width_px;
  float min_coverage;
  float aperture = 0.0f;  ///< m: the lens opening that blurs the rain (0: drawn sharp)
  float focus = 1.0f;     ///< m: camera depth of the plane of focus

  /// Diameter of the disc a point at camera depth `depth` spreads over, measured at that depth:
  /// a thin lens of opening A focused at f blurs it over A·|d − f|/d at the plane of focus,
  /// which is d/f times as large as at the point's own depth.
  [[nodiscard]] float blur_disc(float depth) const {
    return aperture * std::fabs(depth - focus) / focus;
  }
};

/// A number in [0, 1) that depends only on the drop's id (sim's hash): which far drops survive
/// the level of detail is the same in every frame and for every thread count.
float id_unit(std::uint64_t id) { return static_cast<float>(sim::mix64(id) >> 40) * 0x1.0p-24f; }

/// Builds the quad of one far drop; false when it is culled or thinned out. `weight` is the
/// drop's opacity (vanishing), a level-of-detail weight that may exceed 1.
///
/// Radiometry (Garg & Nayar 2006, sim/streak.h): the drop covers each point of its streak for
/// its size over its speed, so the streak's opacity in the middle is min(1, size / travel) and
/// the light it adds is the drop's whatever the exposure. The material gives the drop's
/// radiance (templates/raintrace_materials.inc); this decides only where and how opaque.
bool make_streak(const StreakContext& ctx, std::uint64_t id, const glm::vec3& position,
                 const glm::vec3& velocity, const glm::vec3& acceleration, float diameter,
                 float weight, StreakValue& out) {
  const float speed = glm::length(velocity);
  // A drop at rest (or slower than 1 mm/s) still falls along -y for the quad's orientation.
  const glm::vec3 axis = speed > 1e-3f ? velocity / speed : glm::vec3{0.0f, -1.0f, 0.0f};
  // The drop's outline seen from the side: an ellipse of equal volume flattened along its
  // motion (Beard & Chuang), 2a across and 2b along.
  const auto ratio = static_cast<float>(drop_axis_ratio(diameter));
  // Out of focus, the lens spreads every point of the drop over its blur disc: the drop's image
  // is its outline widened by the disc, and the light it carries, spread over the wider
  // outline, keeps the drop's area of coverage (a defocused drop far smaller than its disc is
  // the lens's bright, hard-edged disc, as it is in night photographs of rain).
  const float blur = ctx.blur_disc(std::max(ctx.view.depth(position), 1e-3f));
  const float sharp_across = diameter / std::cbrt(ratio);
  const float sharp_along = sharp_across * ratio;
  const float across = sharp_across + blur;
  const float along = sharp_along + blur;
  const float spread = (sharp_across * sharp_along) / (across * along);
  const auto travel =
      static_cast<float>(sim::streak_travel(speed, glm::dot(acceleration, axis), ctx.exposure_s));
  float length = travel + along;
  glm::vec3 start = position - axis * (0.5f * along);
  glm::vec3 end = start + axis * length;
  if (!ctx.view.segment_visible(start, end, 0.5f * across)) return false;

  const glm::vec3 middle = 0.5f * (start + end);
  const float depth = std::max(ctx.view.depth(middle), 1e-3f);
  const float pixel = ctx.view.pixel_size(depth, ctx.width_px);
  float alpha = static_cast<float>(sim::streak_opacity(travel, along)) * spread;
  // A drop narrower than a pixel covers only part of the pixels it crosses: draw it a pixel
  // wide at that share (the sub-pixel cells are flat across), not as a wider streak.
  float width = across;
  StreakFootprint footprint = StreakFootprint::resolved;
  if (width < pixel) {
    alpha *= width / pixel;
    width = pixel;
    footprint = StreakFootprint::sub_pixel;
  }
  // Shorter than a pixel (a still drop far away): a pixel long, fainter by the same share.
  if (length < pixel) {
    alpha *= length / pixel;
    const glm::vec3 half = axis * (0.5f * pixel);
    start = middle - half;
    end = middle + half;
    length = pixel;
  }
  alpha = std::min(alpha * std::max(weight, 0.0f), 1.0f);
  // Level of detail: a streak fainter than min_coverage survives with probability
  // alpha / min_coverage and is drawn at min_coverage, so the expected light stays the same
  // while POV-Ray traces a fraction of the quads (each costs a ray hit per pixel it crosses).
  if (alpha < ctx.min_coverage) {
    if (id_unit(id) * ctx.min_coverage >= alpha) return false;
    alpha = ctx.min_coverage;
  }
  out.cell = streak_atlas_cell(ctx.atlas, travel / along, footprint, alpha);
  if (out.cell < 0) return false;

  // Face the camera while staying on the motion axis: side ⟂ axis and ⟂ line of sight.
  glm::vec3 side = glm::cross(axis, ctx.view.eye() - middle);
  const float side_length = glm::length(side);
  side = side_length > 1e-9f ? side / side_length : ctx.view.right();
  side *= 0.5f * width;
  out.corners = {start - side, start + side, end + side, end - side};
  return true;
}

struct DropContext {
  const StreakContext& streaks;
  const sim::Drops& drops;
  float split;  ///< m: nearer drops may be spheres
};

/// Near drops → spheres, far drops → streaks, for drops [begin, end), appended in drop order.
void add_drops(const DropContext& ctx, std::size_t begin, std::size_t end,
               std::vector<SphereValue>& spheres, std::vector<StreakValue>& streaks) {
  const ViewFrustum& view = ctx.streaks.view;
  const sim::Drops& drops = ctx.drops;
  const std::size_t count = drops.size();
  const bool has_acceleration = drops.acceleration.size() == count;
  const bool has_opacity = drops.opacity.size() == count;
  for (std::size_t i = begin; i < end; ++i) {
    const glm::vec3& p = drops.position[i];
    const float diameter = drops.diameter[i];
    const float opacity = has_opacity ? drops.opacity[i] : 1.0f;
    if (!(opacity > 0.0f) || !(diameter > 0.0f)) continue;
    const glm::vec3 acceleration = has_acceleration ? drops.acceleration[i] : glm::vec3{0.0f};
    // Near drops are ray-traced refractive spheres while the camera can see them as drops: at
    // least a pixel across (a sub-pixel sphere is hit by a ray or missed entirely, which
    // speckles the image) and moving less than their own height during the exposure. POV-Ray
    // has no motion blur: a drop that moves further is drawn as its streak, whose radiance is
    // the blurred average of what the drop refracts plus the lights it scatters — what its
    // refraction becomes when spread over more than its size (docs/rain-appearance.md).
    // Out of focus by a pixel or more, it is the lens's disc, drawn as a streak (make_streak).
    const float depth = std::max(view.depth(p), 1e-3f);
    const float pixel = view.pixel_size(depth, ctx.streaks.width_px);
    if (glm::length(p - view.eye()) < ctx.split && diameter >= pixel &&
        ctx.streaks.blur_disc(depth) < pixel) {
      const float radius = 0.5f * diameter;
      const auto ratio = static_cast<float>(drop_axis_ratio(diameter));
      // Equal volume: the horizontal radius grows as the drop flattens, a = R·ratio^(-1/3).
      const float equatorial = radius / std::cbrt(ratio);
      const float height = 2.0f * equatorial * ratio;
      const glm::vec3& v = drops.velocity[i];
      const float speed = glm::length(v);
      const glm::vec3 axis = speed > 1e-3f ? v / speed : glm::vec3{0.0f, -1.0f, 0.0f};
      const auto travel = static_cast<float>(
          sim::streak_travel(speed, glm::dot(acceleration, axis), ctx.streaks.exposure_s));
      if (travel < height) {
        // Swept over its path: centred on it, its height stretched by the travel (the motion is
        // nearly vertical; exposure_s = 0 keeps the drop exactly as it is).
        const glm::vec3 centre = p + axis * (0.5f * travel);
        if (!view.sphere_visible(centre, radius + travel)) continue;
        const float stretched = ratio * (1.0f + travel / height);
        const bool round = std::fabs(stretched - 1.0f) < 1.0f - kRoundEnough;
        spheres.push_back({centre, equatorial, round ? 1.0f : stretched});
        continue;
      }
    }
    StreakValue streak;
    const std::uint64_t id = i < drops.id.size() ? drops.id[i] : i;
    if (make_streak(ctx.streaks, id, p, drops.velocity[i], acceleration, diameter, opacity,
                    streak)) {
      streaks.push_back(streak);
    }
  }
}

/// Drops per chunk of the parallel loop: its spheres and streaks (~200 KB) stay in cache
/// until they are appended. Boundaries depend only on the drop count.
constexpr std::size_t kDropChunk = 4096;

/// add_drops() for all drops into values, on up to `threads` threads: each chunk fills its
/// worker's own vectors; in chunk order, its spheres are appended and its streaks given their
/// place, and then copied there in parallel. The values are the same for every thread count.
void add_drops_in_chunks(const DropContext& ctx, FrameValues& values, int threads) {
  const std::size_t count = ctx.drops.size();
  const std::size_t chunks = (count + kDropChunk - 1) / kDropChunk;
  if (threads <= 1 || chunks <= 1) {
    values.streaks.clear();
    values.streaks.reserve(count);
    add_drops(ctx, 0, count, values.drops, values.streaks);
    return;
  }
  // Room for every drop as a streak; trimmed below. Not cleared first: resize then only
  // zero-fills what the previous frame did not use, not 50 MB per frame.
  values.streaks.resize(count);
  struct Scratch {
    std::vector<SphereValue> spheres;
    std::vector<StreakValue> streaks;
    std::size_t offset = 0;  ///< where this chunk's streaks go in values.streaks
  };
  // One per worker: ordered_chunks() runs at most 64.
  std::vector<Scratch> scratch(static_cast<std::size_t>(std::min(threads, 64)));
  std::size_t streak_count = 0;
  ordered_chunks(
      chunks, threads,
      [&](std::size_t c, std::size_t w) {
        Scratch& mine = scratch[w];
        mine.spheres.clear();
        mine.streaks.clear();
        mine.streaks.reserve(kDropChunk);
        add_drops(ctx, c * kDropChunk, std::min(count, (c + 1) * kDropChunk), mine.spheres,
                  mine.streaks);
      },
      [&](std::size_t, std::size_t w) {
        Scratch& mine = scratch[w];
        values.drops.insert(values.drops.end(), mine.spheres.begin(), mine.spheres.end());
        mine.offset = streak_count;
        streak_count += mine.streaks.size();
      },
      [&](std::size_t, std::size_t w) {
        const Scratch& mine = scratch[w];
        std::copy(mine.streaks.begin(), mine.streaks.end(),
                  values.streaks.begin() + static_cast<std::ptrdiff_t>(mine.offset));
      });
  values.streaks.resize(streak_count);
}

/// Splash droplets are water like the rain and take its path: refractive spheres when near and
/// at least a pixel across, streak quads otherwise (lit like drops, thinned by coverage keyed by
/// their ids). splash_keep of them are kept first, by a hash of the id independent of the
/// coverage thinning's, and carry the light of the rest (opacity / splash_keep).
void add_splash_droplets(const DropContext& ctx, double splash_keep, FrameValues& values) {
  const sim::Drops& droplets = ctx.drops;
  const auto keep = static_cast<float>(std::clamp(splash_keep, 1e-6, 1.0));
  if (keep >= 1.0f) {
    add_drops(ctx, 0, droplets.size(), values.drops, values.streaks);
    return;
  }
  sim::Drops kept;
  for (std::size_t i = 0; i < droplets.size(); ++i) {
    if (id_unit(droplets.id[i] ^ 0x5bd1e995u) >= keep) continue;
    kept.id.push_back(droplets.id[i]);
    kept.position.push_back(droplets.position[i]);
    kept.velocity.push_back(droplets.velocity[i]);
    kept.acceleration.push_back(droplets.acceleration[i]);
    kept.diameter.push_back(droplets.diameter[i]);
    kept.opacity.push_back(droplets.opacity[i] / keep);
  }
  add_drops(DropContext{ctx.streaks, kept, ctx.split}, 0, kept.size(), values.drops,
            values.streaks);
}

glm::vec3 default_flash_position(const ViewFrustum& view) {
  // Sheet lightning from behind the clouds, high and ahead of the camera.
  return view.eye() + view.forward() * 200.0f + glm::vec3{0.0f, 300.0f, 0.0f};
}

}  // namespace

double streak_coverage_threshold(const ExportParams& look) {
  if (look.min_streak_coverage < 0.0) {
    return look.quality == Quality::preview ? kPreviewStreakCoverage : kFinalStreakCoverage;
  }
  return std::min(look.min_streak_coverage, 1.0);
}

FrameValues build_frame_values(const sim::Frame& frame, const ExportParams& look,
                               const StreakAtlasLayout& atlas, int threads) {
  FrameValues values;
  build_frame_values(frame, look, values, atlas, threads);
  return values;
}

void build_frame_values(const sim::Frame& frame, const ExportParams& look, FrameValues& values,
                        const StreakAtlasLayout& atlas, int threads) {
  const ViewFrustum view(look.camera, static_cast<double>(look.width) / look.height);
  values.index = frame.index;
  values.drops.clear();  // (streaks: add_drops_in_chunks)
  values.bolts.clear();

  // The faintest atlas row is the floor of the level of detail: fainter streaks are thinned to
  // it rather than dropped, so no light is lost whatever min_streak_coverage says.
  const double min_coverage =
      std::max(streak_coverage_threshold(look), streak_atlas_faintest_coverage(atlas));
  StreakContext ctx{view, atlas, static_cast<float>(look.camera.exposure_s), look.width,
                    static_cast<float>(min_coverage)};
  if (blurs_rain_only(look)) {
    ctx.aperture = static_cast<float>(look.aperture_m);
    ctx.focus = std::max(view.depth(glm::vec3(look.camera.look_at)), 1e-3f);
  }
  const DropContext drops{ctx, frame.drops, static_cast<float>(look.sphere_distance_m)};
  add_drops_in_chunks(drops, values, threads);

  add_splash_droplets(DropContext{ctx, frame.splashes, drops.split}, look.splash_keep, values);

  values.flash = std::clamp(frame.flash, 0.0f, 1.0f);
  values.flash_position = default_flash_position(view);
  float brightest = -1.0f;
  for (const sim::Bolt& bolt : frame.bolts) {
    // One BoltValue per generation: the main channel carries every return stroke, the branches
    // only the first, fainter with each generation.
    const std::size_t first = values.bolts.size();
    float trunk_radius = 0.0f;  // seen or not, it sets every group's light per metre
    for (const sim::BoltSegment& s : bolt.segments) {
      if (s.generation == 0) trunk_radius = std::max(trunk_radius, s.radius);
      if (!view.segment_visible(s.start, s.end, s.radius)) continue;
      const auto g = static_cast<std::size_t>(std::max(s.generation, 0));
      if (values.bolts.size() < first + g + 1)
        values.bolts.resize(first + g + 1, BoltValue{{}, 0.0f});
      const float depth = std::max(std::min(view.depth(s.start), view.depth(s.end)), 1e-3f);
      const float core = std::max(s.radius, 0.5f * view.pixel_size(depth, look.width));
      values.bolts[first + g].segments.push_back({s.start, s.end, s.radius, core});
    }
    for (std::size_t g = 0; first + g < values.bolts.size(); ++g) {
      const float b = g == 0 ? bolt.brightness
                             : bolt.branch_brightness *
                                   static_cast<float>(sim::branch_brightness(static_cast<int>(g)));
      values.bolts[first + g].brightness = std::max(b, 0.0f);
      if (trunk_radius > 0.0f) values.bolts[first + g].trunk_radius = trunk_radius;
    }
    values.bolts.erase(
        std::remove_if(values.bolts.begin() + static_cast<std::ptrdiff_t>(first),
                       values.bolts.end(), [](const BoltValue& v) { return v.segments.empty(); }),
        values.bolts.end());
    // The light sits at the highest point of the brightest bolt, where the channel meets cloud.
    if (!bolt.segments.empty() && bolt.brightness > brightest) {
      brightest = bolt.brightness;
      values.flash_position = bolt.segments.front().start;
      for (const sim::BoltSegment& s : bolt.segments) {
        if (s.start.y > values.flash_position.y) values.flash_position = s.start;
        if (s.end.y > values.flash_position.y) values.flash_position = s.end;
      }
    }
  }

  // The wet ground: a frame that draws the environment plate shows the plate's puddles (no
  // map); a traced one gets its map of rings and of the film's stir.
  values.ripples = RippleMap{};
  values.ground = ground_applies(look);
  values.time_s = frame.time_s;
  const bool traced =
      !environment_plate_applies(look) || values.flash > 0.0f || !values.bolts.empty();
  if (values.ground && traced) {
    if (!values.ground_pixels.matches(look.camera, look.width, look.height,
                                      look.ground.ground_y_m)) {
      values.ground_pixels =
          GroundPixels(look.camera, look.width, look.height, look.ground.ground_y_m);
    }
    draw_ripples(values.ground_pixels, frame.ripples, values.ripples);
  }
}

}  // namespace raintrace::povgen
