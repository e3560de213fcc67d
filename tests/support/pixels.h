// Decoded pixels of a rendered image, for tests that compare renders (PNG bytes differ between
// identical renders, so tests compare pixels). Header-only; the test links OpenImageIO.
#pragma once

#include <OpenImageIO/imageio.h>
#include <cstddef>
#include <filesystem>
#include <vector>

namespace raintrace::test_support {

/// The image's RGB values, row by row: 0..1 for PNG, scene-linear for EXR; empty when it cannot
/// be read.
inline std::vector<float> read_rgb(const std::filesystem::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) return {};
  const OIIO::ImageSpec& spec = in->spec();
  std::vector<float> px(static_cast<std::size_t>(spec.width) * spec.height * 3);
  in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, px.data());
  return px;
}

}  // namespace raintrace::test_support
