// Heat-map difference images with a labelled scale bar, drawn with a built-in 3×5 pixel font so
// the labels need no font files and come out identical on every machine.
#include "compare/diff_image.h"

#include <fmt/core.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "compare/metrics.h"

namespace raintrace::compare {

namespace {

// Each glyph is 5 rows of 3 bits, most significant bit on the left.
struct Glyph {
  char ch;
  std::array<std::uint8_t, 5> rows;
};
constexpr std::array<Glyph, 15> kFont{{
    {'0', {7, 5, 5, 5, 7}},
    {'1', {2, 6, 2, 2, 7}},
    {'2', {7, 1, 7, 4, 7}},
    {'3', {7, 1, 7, 1, 7}},
    {'4', {5, 5, 7, 1, 1}},
    {'5', {7, 4, 7, 1, 7}},
    {'6', {7, 4, 7, 5, 7}},
    {'7', {7, 1, 1, 1, 1}},
    {'8', {7, 5, 7, 5, 7}},
    {'9', {7, 5, 7, 1, 7}},
    {'.', {0, 0, 0, 0, 2}},
    {'e', {0, 7, 7, 4, 7}},
    {'-', {0, 0, 7, 0, 0}},
    {'+', {0, 2, 7, 2, 0}},
    {' ', {0, 0, 0, 0, 0}},
}};

// Text width in pixels at a scale: 3 columns + 1 gap per character.
int text_width(const std::string& text, int scale) { return int(text.size()) * 4 * scale; }

void draw_text(Image& img, const std::string& text, int x0, int y0, int scale) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto it =
        std::find_if(kFont.begin(), kFont.end(), [&](const Glyph& g) { return g.ch == text[i]; });
    if (it == kFont.end()) continue;
    for (int row = 0; row < 5; ++row) {
      for (int col = 0; col < 3; ++col) {
        if (!((it->rows[row] >> (2 - col)) & 1)) continue;
        for (int dy = 0; dy < scale; ++dy) {
          for (int dx = 0; dx < scale; ++dx) {
            const int x = x0 + (int(i) * 4 + col) * scale + dx, y = y0 + row * scale + dy;
            if (x < 0 || y < 0 || x >= img.width || y >= img.height) continue;
            for (int c = 0; c < 3; ++c) img.at(x, y, c) = 1.0f;
          }
        }
      }
    }
  }
}

std::string label(double value) { return value == 0.0 ? "0" : fmt::format("{:.3g}", value); }

}  // namespace

double auto_full_scale(double max_error) {
  const double floor = 1.0 / 255.0;
  if (!(max_error > floor) || !std::isfinite(max_error)) {
    return std::isfinite(max_error) ? floor : 1.0;
  }
  const double decade = std::pow(10.0, std::floor(std::log10(max_error)));
  for (double step : {1.0, 2.0, 5.0, 10.0}) {
    // A tiny tolerance so an error of exactly 0.2 maps to 0.2, not 0.5.
    if (max_error <= step * decade * (1.0 + 1e-12)) return step * decade;
  }
  return 10.0 * decade;
}

int scale_bar_height(int width) { return 16 * std::max(1, width / 320); }

void heat_colour(double t, float rgb[3]) {
  t = std::clamp(std::isnan(t) ? 1.0 : t, 0.0, 1.0);
  // black → red over [0, 1/3], red → yellow over [1/3, 2/3], yellow → white over [2/3, 1].
  rgb[0] = float(std::min(1.0, 3.0 * t));
  rgb[1] = float(std::clamp(3.0 * t - 1.0, 0.0, 1.0));
  rgb[2] = float(std::clamp(3.0 * t - 2.0, 0.0, 1.0));
}

Image difference_heatmap(const Image& a, const Image& b, double full_scale) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels) {
    throw std::invalid_argument(fmt::format("difference image needs equal sizes, got {} and {}",
                                            size_string(a), size_string(b)));
  }
  std::vector<double> error(a.pixel_count(), 0.0);
  double max_error = 0.0;
  for (std::size_t i = 0; i < error.size(); ++i) {
    for (int c = 0; c < a.channels; ++c) {
      const double va = a.pixels[i * a.channels + c], vb = b.pixels[i * a.channels + c];
      double e = std::abs(va - vb);
      if (std::isnan(e)) e = (std::isnan(va) && std::isnan(vb)) ? 0.0 : HUGE_VAL;
      error[i] = std::max(error[i], e);
    }
    max_error = std::max(max_error, error[i]);
  }
  if (!(full_scale > 0.0)) full_scale = auto_full_scale(max_error);

  const int bar = scale_bar_height(a.width), scale = bar / 16;
  Image out(a.width, a.height + bar, 3, 0.1f);
  out.channel_names = {"R", "G", "B"};
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      heat_colour(error[std::size_t(y) * a.width + x] / full_scale, &out.at(x, y, 0));
    }
  }
  // The ramp: 6·scale rows spanning the width minus a margin, then the labels under it.
  const int margin = 2 * scale, ramp_top = a.height + 2 * scale;
  const int ramp_width = std::max(1, a.width - 2 * margin);
  for (int x = 0; x < ramp_width && margin + x < a.width; ++x) {
    float rgb[3];
    heat_colour(ramp_width > 1 ? double(x) / (ramp_width - 1) : 1.0, rgb);
    for (int y = ramp_top; y < ramp_top + 5 * scale; ++y) {
      for (int c = 0; c < 3; ++c) out.at(margin + x, y, c) = rgb[c];
    }
  }
  const int text_top = ramp_top + 6 * scale;
  const std::string lo = "0", mid = label(full_scale / 2.0), hi = label(full_scale);
  draw_text(out, lo, margin, text_top, scale);
  draw_text(out, hi, a.width - margin - text_width(hi, scale) + scale, text_top, scale);
  const int mid_x = (a.width - text_width(mid, scale)) / 2;
  // Only when it does not collide with the end labels (narrow images show just 0 and full).
  if (mid_x > margin + text_width(lo, scale) + 2 * scale &&
      mid_x + text_width(mid, scale) < a.width - margin - text_width(hi, scale)) {
    draw_text(out, mid, mid_x, text_top, scale);
  }
  return out;
}

}  // namespace raintrace::compare
