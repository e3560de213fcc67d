// Streak atlas pixels (pure) and their PNG file (OpenImageIO, kept out of the header).
#include "povgen/streak_atlas.h"

#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "sim/streak.h"

namespace raintrace::povgen {

double StreakAtlasLayout::row_opacity(int row) const {
  return std::exp2(-static_cast<double>(row) / kStreakRowsPerHalving);
}

double streak_atlas_motion(const StreakAtlasLayout& layout, int motion_column) {
  (void)layout;
  return motion_column <= 0 ? 0.0 : std::exp2(motion_column - 2);
}

double streak_profile(double motion, StreakFootprint footprint, double along, double across) {
  // A drop of diameter 1 moving `motion`: the streak is 1 + motion long.
  const double length = 1.0 + motion;
  const double middle = sim::streak_opacity(motion, 1.0);
  const double s = along * length;
  if (footprint == StreakFootprint::resolved) {
    return sim::streak_time_coverage(s, 0.5 * across, motion, 1.0) / middle;
  }
  // Integrated across the disc (midpoint rule, 64 chords: the disc's area to 0.1 %).
  constexpr int kChords = 64;
  double sum = 0.0;
  for (int j = 0; j < kChords; ++j) {
    sum += sim::streak_time_coverage(s, -0.5 + (j + 0.5) / kChords, motion, 1.0);
  }
  return sum / kChords / middle;
}

namespace {

StreakFootprint column_footprint(const StreakAtlasLayout& layout, int column) {
  return column < layout.motions ? StreakFootprint::resolved : StreakFootprint::sub_pixel;
}

/// A column's texels before the row's opacity, peak 1, the cell's own rows bottom to top. The
/// frames map a quad's corners to the centres of the cell's corner texels and POV-Ray
/// interpolates bilinearly between texel centres, so texel (cx, cy) holds the profile at quad
/// position (cx/(w − 1), cy/(h − 1)), edges included.
std::vector<double> column_texels(const StreakAtlasLayout& layout, int column) {
  const int w = layout.cell_width;
  const int h = layout.cell_height;
  const double motion = streak_atlas_motion(layout, column % layout.motions);
  std::vector<double> texels(static_cast<std::size_t>(w) * h);
  double peak = 0.0;
  for (int cy = 0; cy < h; ++cy) {
    // cy = 0 is the cell's bottom texel row = the streak's leading end (quad corners 2, 3).
    const double along = 1.0 - static_cast<double>(cy) / (h - 1);
    for (int cx = 0; cx < w; ++cx) {
      const double across = 2.0 * cx / (w - 1) - 1.0;
      const double value = streak_profile(motion, column_footprint(layout, column), along, across);
      texels[static_cast<std::size_t>(cy) * w + cx] = value;
      peak = std::max(peak, value);
    }
  }
  if (peak > 0.0) {
    for (double& t : texels) t /= peak;
  }
  return texels;
}

/// Opacity a cell row must have for the column's quad to carry `1` of the drop's coverage:
/// the exact mean of the profile over the quad, π/4 / (middle × (1 + motion)), over the mean
/// POV-Ray's bilinear filter gives the texels (the trapezoid rule). The latter misses by a few %
/// for 8 texels across a round outline, and the texels are scaled to peak 1.
double column_gain(const StreakAtlasLayout& layout, int column) {
  const std::vector<double> texels = column_texels(layout, column);
  const int w = layout.cell_width;
  const int h = layout.cell_height;
  double trapezoid = 0.0;
  for (int cy = 0; cy < h; ++cy) {
    const double wy = (cy == 0 || cy == h - 1) ? 0.5 : 1.0;
    for (int cx = 0; cx < w; ++cx) {
      const double wx = (cx == 0 || cx == w - 1) ? 0.5 : 1.0;
      trapezoid += wx * wy * texels[static_cast<std::size_t>(cy) * w + cx];
    }
  }
  trapezoid /= static_cast<double>((w - 1) * (h - 1));
  const double motion = streak_atlas_motion(layout, column % layout.motions);
  const double exact = std::numbers::pi / 4.0 / (sim::streak_opacity(motion, 1.0) * (1.0 + motion));
  return trapezoid > 0.0 ? exact / trapezoid : 1.0;
}

/// column_gain() of every column, computed once per layout and thread (a frame's streaks all
/// use the same layout; the threads building them each keep their own copy).
const std::vector<double>& column_gains(const StreakAtlasLayout& layout) {
  thread_local StreakAtlasLayout cached{0, 0, 0, 0};
  thread_local std::vector<double> gains;
  if (cached.motions != layout.motions || cached.cell_width != layout.cell_width ||
      cached.cell_height != layout.cell_height) {
    gains.clear();
    for (int column = 0; column < layout.columns(); ++column) {
      gains.push_back(column_gain(layout, column));
    }
    cached = layout;
  }
  return gains;
}

}  // namespace

double streak_atlas_column_gain(const StreakAtlasLayout& layout, int column) {
  return column_gains(layout).at(static_cast<std::size_t>(column));
}

double streak_atlas_faintest_coverage(const StreakAtlasLayout& layout) {
  const std::vector<double>& gains = column_gains(layout);
  return layout.faintest_opacity() / *std::min_element(gains.begin(), gains.end());
}

std::vector<std::uint16_t> streak_atlas_pixels(const StreakAtlasLayout& layout) {
  if (layout.motions < 1 || layout.opacity_levels < 1 || layout.cell_width < 2 ||
      layout.cell_height < 2) {
    throw std::invalid_argument("streak atlas layout needs at least 1×1 cells of 2×2 pixels");
  }
  const int width = layout.width();
  const int height = layout.height();
  std::vector<std::vector<double>> profiles;
  for (int column = 0; column < layout.columns(); ++column) {
    profiles.push_back(column_texels(layout, column));
  }
  std::vector<std::uint16_t> pixels(static_cast<std::size_t>(width) * height * 2);
  for (int py = 0; py < height; ++py) {
    const int row = (height - 1 - py) / layout.cell_height;
    const int cy = (height - 1 - py) % layout.cell_height;
    const double opacity = layout.row_opacity(row);
    for (int px = 0; px < width; ++px) {
      const auto& profile = profiles[static_cast<std::size_t>(px / layout.cell_width)];
      const double a =
          opacity *
          profile[static_cast<std::size_t>(cy) * layout.cell_width + px % layout.cell_width];
      auto* p = &pixels[(static_cast<std::size_t>(py) * width + px) * 2];
      // White: the material's finish and the lights give the colour, and the rain mask can
      // use the same atlas for pure white.
      p[0] = 65535;
      p[1] = static_cast<std::uint16_t>(std::lround(std::clamp(a, 0.0, 1.0) * 65535.0));
    }
  }
  return pixels;
}

void write_streak_atlas(const std::filesystem::path& path, const StreakAtlasLayout& layout) {
  const std::vector<std::uint16_t> pixels = streak_atlas_pixels(layout);
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) {
    throw std::runtime_error("cannot write streak atlas " + path.string() + ": " +
                             OIIO::geterror());
  }
  OIIO::ImageSpec spec(layout.width(), layout.height(), 2, OIIO::TypeDesc::UINT16);
  spec.channelnames = {"Y", "A"};
  spec.alpha_channel = 1;
  // The alpha is coverage and the grey is white regardless: PNG's unassociated alpha as is.
  spec.attribute("oiio:UnassociatedAlpha", 1);
  if (!out->open(path.string(), spec) || !out->write_image(OIIO::TypeDesc::UINT16, pixels.data()) ||
      !out->close()) {
    throw std::runtime_error("cannot write streak atlas " + path.string() + ": " + out->geterror());
  }
}

namespace {

/// round(−8·log2 x) for x in (0, 1], without libm: it runs once per streak, a million times a
/// frame. With x = m·2^e, m in [1, 2): −8·log2 x = −8e − 8·log2 m, and round(8·log2 m) counts
/// the thresholds 2^((j − ½)/8), j = 1…8, that m reaches.
int nearest_row_step(double x) {
  static_assert(kStreakRowsPerHalving == 8, "the thresholds below are for 8 rows per halving");
  static constexpr std::array<double, 8> kThresholds{
      1.0442737824274138, 1.1387886347566916, 1.241857812073484,  1.3542555469368927,
      1.4768261459394993, 1.6104903319492543, 1.7562521603732995, 1.9152065613971474};
  const auto bits = std::bit_cast<std::uint64_t>(x);
  const auto biased_exponent = static_cast<int>(bits >> 52);         // x > 0: no sign bit
  if (biased_exponent == 0) return std::numeric_limits<int>::max();  // subnormal: far too faint
  const double mantissa =
      std::bit_cast<double>((bits & 0x000F'FFFF'FFFF'FFFFULL) | 0x3FF0'0000'0000'0000ULL);
  int up = 0;
  for (const double threshold : kThresholds) up += mantissa >= threshold ? 1 : 0;
  return -kStreakRowsPerHalving * (biased_exponent - 1023) - up;
}

}  // namespace

int streak_atlas_cell(const StreakAtlasLayout& layout, double motion, StreakFootprint footprint,
                      double opacity) {
  if (!(opacity > 0.0)) return -1;
  // Column: 0 for a drop that moves less than 2^−1.5 of its size, then the nearest of 0.5, 1,
  // 2, … in log2: one more column for each 2^(k − 1.5) the motion reaches.
  int column = 0;
  for (double threshold = 0.35355339059327379; column < layout.motions - 1 && motion >= threshold;
       threshold *= 2.0) {
    ++column;
  }
  // The column draws the profile of its own motion m_c over a quad (1 + m_c) sizes long, but
  // the quad is (1 + m) long: its middle opacity is scaled so that the quad still carries the
  // drop's area, min(1, 1/m)·(1 + m) = min(1, 1/m_c)·(1 + m_c) in the middle's units. Without
  // this a streak between two columns carried up to ±7 % of the drop's light (a long streak,
  // beyond the last column's 32 sizes, 2 % too little).
  const auto middle_length = [](double m) { return (m > 1.0 ? 1.0 / m : 1.0) * (1.0 + m); };
  const double drawn = streak_atlas_motion(layout, column);
  const double carried = opacity * middle_length(drawn) / middle_length(std::max(motion, 0.0));
  if (footprint == StreakFootprint::sub_pixel) column += layout.motions;
  const double gained =
      std::min(carried, 1.0) * column_gains(layout)[static_cast<std::size_t>(column)];
  const int row = nearest_row_step(std::min(gained, 1.0));
  if (row >= layout.opacity_levels) return -1;
  return row * layout.columns() + column;
}

}  // namespace raintrace::povgen
