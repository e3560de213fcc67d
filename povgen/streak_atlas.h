// The streak texture atlas (textures/streak_atlas.png): a grid of motion-blurred drop images.
// Columns go from a spherical drop to a flattened, hemispheric one (the paper's texture set,
// with interpolated in-between shapes); rows halve the opacity from one row to the next, so a
// streak widened to a whole pixel keeps the light of a thinner one (see frame_values.h).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace raintrace::povgen {

struct StreakAtlasLayout {
  /// Drop shapes across, from axis ratio 1 (sphere) to 0.5 (flattened). Default 8.
  int shapes = 8;
  /// Opacity levels down: row r has peak opacity 2^-r. Default 8 (1 … 1/128).
  int opacity_levels = 8;
  /// Pixels of one cell across the streak. Default 16.
  int cell_width = 16;
  /// Pixels of one cell along the streak. Default 64.
  int cell_height = 64;

  [[nodiscard]] int cells() const { return shapes * opacity_levels; }
  [[nodiscard]] int width() const { return shapes * cell_width; }
  [[nodiscard]] int height() const { return opacity_levels * cell_height; }
};

/// The atlas pixels, 8-bit RGBA, rows top to bottom. Pure and deterministic.
std::vector<std::uint8_t> streak_atlas_pixels(const StreakAtlasLayout& layout);

/// Writes the atlas as PNG with OpenImageIO. Throws std::runtime_error naming the path.
void write_streak_atlas(const std::filesystem::path& path, const StreakAtlasLayout& layout);

/// Cell of a shape (axis ratio in [0.5, 1]) and opacity (0..1]: row-major index, or -1 when
/// the opacity is below the faintest row's half (nothing visible is lost by not writing it).
int streak_atlas_cell(const StreakAtlasLayout& layout, double axis_ratio, double opacity);

}  // namespace raintrace::povgen
