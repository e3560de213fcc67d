// The streak texture atlas (textures/streak_atlas.png): how opaque each point of a streak is,
// for the streak quads of frames/frame_NNNN.pov. A drop covers a point of its streak for the
// share of the exposure it takes to pass over it (sim/streak.h, Garg & Nayar 2006), so the
// picture of a streak depends on how far the drop moves in the exposure compared with its own
// size (columns), and on whether the drop is wider than a pixel (its rounded outline shows) or
// narrower (only its coverage of the pixel counts: flat across). Rows scale the opacity in steps
// of 2^(1/8), so the nearest row is within 4.4 % of any opacity. 16-bit grey + alpha: the
// faintest rows are far below 8-bit alpha's 1/255.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace raintrace::povgen {

/// Whether a streak's drop is at least a pixel wide on screen.
enum class StreakFootprint {
  resolved,   ///< its outline shows: the cell holds the swept disc's coverage
  sub_pixel,  ///< widened to one pixel: the cell holds the coverage averaged across, flat
};

/// Rows per halving of the opacity: neighbouring rows differ by 2^(1/8) = 9 %.
inline constexpr int kStreakRowsPerHalving = 8;

struct StreakAtlasLayout {
  /// Columns per footprint: motion during the exposure over the drop's size, 0 (a still drop:
  /// a disc), then 0.5, 1, 2, … 2^(motions − 3). Default 8 (up to 32: ends shorter than 3 %).
  int motions = 8;
  /// Rows: row r has opacity 2^(−r / kStreakRowsPerHalving). Default 105: 1 … 2^−13 (1.2e-4).
  int opacity_levels = 105;
  /// Pixels of one cell across the streak. Default 8.
  int cell_width = 8;
  /// Pixels of one cell along the streak. Default 32.
  int cell_height = 32;

  /// Columns: the resolved footprint's motions, then the sub-pixel footprint's.
  [[nodiscard]] int columns() const { return 2 * motions; }
  [[nodiscard]] int cells() const { return columns() * opacity_levels; }
  [[nodiscard]] int width() const { return columns() * cell_width; }
  [[nodiscard]] int height() const { return opacity_levels * cell_height; }
  /// Opacity of row r: 2^(−r / kStreakRowsPerHalving).
  [[nodiscard]] double row_opacity(int row) const;
  /// Opacity of the faintest row.
  [[nodiscard]] double faintest_opacity() const { return row_opacity(opacity_levels - 1); }
};

/// Motion in drop sizes that a column stands for: 0, 0.5, 1, 2, …
double streak_atlas_motion(const StreakAtlasLayout& layout, int motion_column);

/// Profile of a streak in a column, before the row's opacity and the peak-1 scaling of the
/// stored texels: (along in [0, 1] from the trailing end, across in [−1, 1]). Resolved: the swept
/// disc's time coverage divided by the middle's min(1, D/travel), so 1 in the middle of the streak.
/// Sub-pixel: the coverage integrated across the disc and divided by (diameter × the middle's
/// opacity), flat across: π/4 in the middle of a long streak. Either way a quad of the drop's width
/// (resolved) or of any width w with opacity × D/w (sub-pixel) carries exactly the drop's area of
/// coverage.
double streak_profile(double motion, StreakFootprint footprint, double along, double across);

/// How much the opacity of a cell's row must exceed the streak's coverage for the quad to carry
/// the drop's whole area: a column holds its profile scaled to peak 1 and sampled at the texel
/// centres POV-Ray filters bilinearly (quad corners on the corner texels), whose integral
/// misses the exact one by a few %. streak_atlas_cell() applies it.
double streak_atlas_column_gain(const StreakAtlasLayout& layout, int column);

/// The faintest coverage every column can draw: faintest_opacity() over the smallest column
/// gain. frame_values thins fainter streaks to it, so none falls off the atlas.
double streak_atlas_faintest_coverage(const StreakAtlasLayout& layout);

/// The atlas pixels: 16-bit grey + alpha pairs (grey always white), rows top to bottom, row 0
/// of the image is the top. Cell (row r, column c) sits r·cell_height from the *bottom* (POV-Ray's
/// v runs upward) and c·cell_width from the left; its bottom texel row is the streak's leading
/// end. Pure and deterministic.
std::vector<std::uint16_t> streak_atlas_pixels(const StreakAtlasLayout& layout);

/// Writes the atlas as a 16-bit grey + alpha PNG with OpenImageIO. Throws std::runtime_error
/// naming the path.
void write_streak_atlas(const std::filesystem::path& path, const StreakAtlasLayout& layout);

/// Cell for a streak: motion = travel during the exposure / the drop's size along it (nearest
/// column in log2; under 0.35 the still column), its footprint, and its opacity in the middle
/// (rescaled to the column's motion so that a quad (1 + motion) sizes long carries the drop's
/// area, times the column's gain, the nearest row in log2; above 1 counts as 1). −1 when the
/// opacity is not positive or below the faintest row by more than half a step (callers thin such
/// streaks to faintest_opacity()).
int streak_atlas_cell(const StreakAtlasLayout& layout, double motion, StreakFootprint footprint,
                      double opacity);

}  // namespace raintrace::povgen
