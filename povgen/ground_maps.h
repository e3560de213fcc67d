// The ground as the camera sees it, in images POV-Ray looks up per pixel: the puddle mask
// (textures/puddle_mask.png, once) and each frame's ripple map (ripples/ripple_NNNN.png).
//
// Both are in screen space: texel (i, j) holds the ground where the ray through pixel (i, j)
// meets it. templates/raintrace_ground.inc projects a ground point back to its texel, so each
// pixel reads its own ground, and detail follows the size of a pixel by itself: a ring narrower
// than a pixel is already averaged away here (sim/ripples.h's pixel filter) instead of
// shimmering in POV-Ray, and the map costs the same whether the rain is light or heavy.
//
// The ripple map is a 16-bit gray + alpha PNG: gray the puddles' water height (0.5 where flat),
// alpha how calm the film between the puddles is: 1 − the stir of fresh hits there (their
// short-lived dimples, too small to draw as rings at the camera's distance, darken its
// reflection). Calm ground, the puddles' water among it, is exactly 1 (opaque: POV-Ray reads the
// channels as they are, other readers may premultiply), the end of the texture_map where POV-Ray
// shades one texture instead of blending two; the stir is read without interpolation, so that a
// stirred pixel never blends into its neighbours. Where the puddles are, and their shorelines,
// the mask says (sim/puddles.h's share, drawn by templates/raintrace_ground.inc).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "sim/camera.h"
#include "sim/frame.h"
#include "sim/puddles.h"
#include "sim/ripples.h"

namespace raintrace::povgen {

/// Height range of the ripple map, m: R = 0.5 + height / kRippleHeightRange.
inline constexpr double kRippleHeightRange = 0.004;

/// Where each pixel's ray meets the ground plane y = ground_y (pixel centres, the camera of
/// POV-Ray's `camera { location look_at right x*aspect angle fov }`).
class GroundPixels {
 public:
  GroundPixels() = default;
  GroundPixels(const sim::Camera& camera, int width, int height, double ground_y);

  [[nodiscard]] int width() const { return m_width; }
  [[nodiscard]] int height() const { return m_height; }
  /// True if pixel p (row-major, top row first) sees the ground within sim's impact range.
  [[nodiscard]] bool hits(std::size_t p) const { return m_across[p] > 0.0f; }
  [[nodiscard]] float x(std::size_t p) const { return m_x[p]; }
  [[nodiscard]] float z(std::size_t p) const { return m_z[p]; }
  /// The ground pixel p spans (across and along the line of sight, whose horizontal direction
  /// it gives): what the ripples are filtered by.
  [[nodiscard]] sim::PixelSpan span(std::size_t p) const;
  /// Pixel column and row of a ground point (may lie outside the image); false if behind.
  bool project(double x, double z, double& column, double& row) const;
  /// True if built for this camera, size and ground.
  [[nodiscard]] bool matches(const sim::Camera& camera, int width, int height,
                             double ground_y) const;

 private:
  sim::Camera m_camera;
  double m_ground_y = 0.0;
  int m_width = 0, m_height = 0;
  glm::dvec3 m_eye{}, m_forward{}, m_right{}, m_up{};
  double m_tan_x = 0.0, m_tan_y = 0.0;
  std::vector<float> m_x, m_z, m_across, m_along, m_dir;
};

/// Share of each pixel's ground under a puddle (0..1, 0 where the pixel sees no ground), row
/// major, top row first.
std::vector<float> puddle_mask(const GroundPixels& pixels, const sim::PuddleField& puddles);

/// One frame's ripples as the camera sees them.
struct RippleMap {
  int width = 0, height = 0;
  std::vector<float> height_m;  ///< water height, m
  std::vector<float> film;      ///< how stirred the film between puddles is, 0..1
  [[nodiscard]] bool empty() const { return height_m.empty(); }
};

/// Draws the ripples into `map`, resized to the pixels.
void draw_ripples(const GroundPixels& pixels, const std::vector<sim::Ripple>& ripples,
                  RippleMap& map);

/// Writes an 8-bit gray PNG of values in [0, 1] (the puddle mask). Throws std::runtime_error.
void write_mask_png(const std::filesystem::path& path, int width, int height,
                    const std::vector<float>& values);
/// Writes the ripple map as a 16-bit gray + alpha PNG. Throws std::runtime_error.
void write_ripple_png(const std::filesystem::path& path, const RippleMap& map);
/// The pixels write_ripple_png() encodes, 16-bit gray + alpha: what a frame's input hash covers.
std::vector<std::uint16_t> ripple_pixels(const RippleMap& map);

}  // namespace raintrace::povgen
