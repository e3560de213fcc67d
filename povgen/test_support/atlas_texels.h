// Test support, not part of raintrace_povgen: reading the streak atlas's pixels back as POV-Ray
// draws them, for tests that check what light a cell (and a quad drawn with it) carries.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "povgen/streak_atlas.h"

namespace raintrace::povgen::test_support {

/// Alpha (0..1) of a texel of cell (row, column) in streak_atlas_pixels(l), texel (cx, cy) with
/// cy = 0 the cell's bottom.
inline double atlas_alpha_at(const std::vector<std::uint16_t>& px, const StreakAtlasLayout& l,
                             int row, int column, int cx, int cy) {
  const int x = column * l.cell_width + cx;
  const int y = l.height() - 1 - (row * l.cell_height + cy);
  return px[(static_cast<std::size_t>(y) * l.width() + x) * 2 + 1] / 65535.0;
}

/// Mean of a cell as POV-Ray's bilinear filter spreads it over a quad whose corners sit on the
/// centres of the cell's corner texels: the trapezoid rule over the texels.
inline double atlas_cell_mean(const std::vector<std::uint16_t>& px, const StreakAtlasLayout& l,
                              int row, int column) {
  double sum = 0.0;
  for (int cy = 0; cy < l.cell_height; ++cy) {
    const double wy = (cy == 0 || cy == l.cell_height - 1) ? 0.5 : 1.0;
    for (int cx = 0; cx < l.cell_width; ++cx) {
      const double wx = (cx == 0 || cx == l.cell_width - 1) ? 0.5 : 1.0;
      sum += wx * wy * atlas_alpha_at(px, l, row, column, cx, cy);
    }
  }
  return sum / ((l.cell_width - 1) * (l.cell_height - 1));
}

}  // namespace raintrace::povgen::test_support
