// Streak atlas pixels (pure) and their PNG file (OpenImageIO, kept out of the header).
#include "povgen/streak_atlas.h"

#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace raintrace::povgen {
namespace {

/// Opacity of a motion-blurred drop at (x across in [-1, 1], y along in [0, 1], 0 = trailing
/// end) for a drop of the given flatness (0 = sphere, 1 = flattened/hemispheric).
double streak_alpha(double x, double y, double flatness) {
  // Across: nearly flat with soft rims. Far streaks are widened to one pixel and sampled once
  // per pixel without antialiasing; a peaked profile would turn them into speckle.
  const double across = std::sqrt(std::clamp((1.0 - std::fabs(x)) * 2.5, 0.0, 1.0));
  // Along: the end caps are the drop's outline swept by the motion. The trailing cap is the
  // drop's round top; the leading cap is its bottom, which flattens as the drop does.
  const double trailing_cap = 0.18;
  const double leading_cap = 0.18 * (1.0 - 0.8 * flatness);
  double along = 1.0;
  // The cap follows the outline: at distance d into a cap of length c the chord is
  // sqrt(1 − (1 − d/c)²) of the full width; a smoothstep in d/c fades the tip to clear so
  // filtering never smears a hard end.
  auto cap = [x](double d, double c) {
    const double s = std::clamp(d / c, 0.0, 1.0);
    const double t = 1.0 - s;
    const double chord = std::sqrt(std::max(0.0, 1.0 - t * t));
    return std::clamp((chord - std::fabs(x)) * 4.0, 0.0, 1.0) * s * s * (3.0 - 2.0 * s);
  };
  if (y < trailing_cap) along = cap(y, trailing_cap);
  if (1.0 - y < leading_cap) along = cap(1.0 - y, leading_cap);
  // Water is brighter where the drop is thicker and where the drop lingered: the paper's
  // textures fade slightly toward the trailing end (the drop accelerates through the exposure).
  const double fade = 0.85 + 0.15 * y;
  return across * along * fade;
}

}  // namespace

std::vector<std::uint8_t> streak_atlas_pixels(const StreakAtlasLayout& layout) {
  if (layout.shapes < 1 || layout.opacity_levels < 1 || layout.cell_width < 2 ||
      layout.cell_height < 2) {
    throw std::invalid_argument("streak atlas layout needs at least 1×1 cells of 2×2 pixels");
  }
  const int width = layout.width();
  const int height = layout.height();
  std::vector<std::uint8_t> pixels(static_cast<std::size_t>(width) * height * 4);
  for (int py = 0; py < height; ++py) {
    // Image rows run top to bottom; POV-Ray's v runs bottom to top. Row 0 of the atlas (full
    // opacity) is the bottom band so that cell index = row·shapes + column reads naturally in v.
    const int level = (height - 1 - py) / layout.cell_height;
    const int cy = (height - 1 - py) % layout.cell_height;
    const double opacity = std::ldexp(1.0, -level);
    // v = 0 at the cell's bottom = the streak's leading end (quad corners 2, 3 sit there).
    const double along = 1.0 - (cy + 0.5) / layout.cell_height;
    for (int px = 0; px < width; ++px) {
      const int shape = px / layout.cell_width;
      const int cx = px % layout.cell_width;
      const double flatness =
          layout.shapes > 1 ? static_cast<double>(shape) / (layout.shapes - 1) : 0.0;
      const double x = 2.0 * (cx + 0.5) / layout.cell_width - 1.0;
      const double a = opacity * streak_alpha(x, along, flatness);
      auto* p = &pixels[(static_cast<std::size_t>(py) * width + px) * 4];
      // White: the material's finish and the lights give the colour, and the rain mask can
      // use the same atlas for pure white.
      p[0] = 255;
      p[1] = 255;
      p[2] = 255;
      p[3] = static_cast<std::uint8_t>(std::lround(std::clamp(a, 0.0, 1.0) * 255.0));
    }
  }
  return pixels;
}

void write_streak_atlas(const std::filesystem::path& path, const StreakAtlasLayout& layout) {
  const std::vector<std::uint8_t> pixels = streak_atlas_pixels(layout);
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) {
    throw std::runtime_error("cannot write streak atlas " + path.string() + ": " +
                             OIIO::geterror());
  }
  const OIIO::ImageSpec spec(layout.width(), layout.height(), 4, OIIO::TypeDesc::UINT8);
  if (!out->open(path.string(), spec) || !out->write_image(OIIO::TypeDesc::UINT8, pixels.data()) ||
      !out->close()) {
    throw std::runtime_error("cannot write streak atlas " + path.string() + ": " + out->geterror());
  }
}

namespace {

/// round(−log2 x) for x in (0, 1], without libm: it runs once per streak, a million times a
/// frame, and log2 + lround were a fifth of the frame values' time. With x = m·2^e and m in
/// [0.5, 1), −log2 x = −e − log2 m, where −log2 m in (0, 1] rounds up exactly when m ≤ √½.
int nearest_halving(double x) {
  const auto bits = std::bit_cast<std::uint64_t>(x);
  const auto biased_exponent = static_cast<int>(bits >> 52);         // x > 0: no sign bit
  if (biased_exponent == 0) return std::numeric_limits<int>::max();  // subnormal: far too faint
  const double mantissa =
      std::bit_cast<double>((bits & 0x000F'FFFF'FFFF'FFFFULL) | 0x3FE0'0000'0000'0000ULL);
  return 1022 - biased_exponent + (mantissa <= std::numbers::sqrt2 / 2 ? 1 : 0);
}

}  // namespace

int streak_atlas_cell(const StreakAtlasLayout& layout, double axis_ratio, double opacity) {
  // Rows halve the opacity: the nearest row in log2 keeps a streak within a factor √2.
  if (!(opacity > 0.0)) return -1;
  const int row = nearest_halving(std::min(opacity, 1.0));
  if (row >= layout.opacity_levels) return -1;
  const double flatness = std::clamp((1.0 - axis_ratio) / 0.5, 0.0, 1.0);
  // Rounds half up, as lround does for these non-negative numbers.
  const auto column = static_cast<int>(flatness * (layout.shapes - 1) + 0.5);
  return row * layout.shapes + column;
}

}  // namespace raintrace::povgen
