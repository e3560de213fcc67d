// The film's pixel-sized settings — grain, sensor noise, the lens's softness — are documented in
// pixels of a frame 1920 wide, so a scene developed smaller looks the same, only coarser.
#pragma once

namespace raintrace::film {

/// The width, in pixels, at which the pixel-sized settings hold as written.
inline constexpr double kDocumentedWidth = 1920.0;

/// `size` pixels of a 1920-wide frame, in pixels of a frame `width` wide.
constexpr double at_width(double size, int width) { return size * (width / kDocumentedWidth); }

}  // namespace raintrace::film
