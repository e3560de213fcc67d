// OpenImageIO-backed reading of HDR frames and writing of developed PNGs.
#include "film/image_file.h"

#include <fmt/core.h>

#include <OpenImageIO/imageio.h>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace raintrace::film {

RgbImage read_rgb_image(const std::filesystem::path& path) {
  auto input = OIIO::ImageInput::open(path.string());
  if (!input) {
    throw std::runtime_error(
        fmt::format("cannot read image '{}': {}", path.string(), OIIO::geterror()));
  }
  const OIIO::ImageSpec& spec = input->spec();
  if (spec.depth > 1 || spec.nchannels < 1) {
    throw std::runtime_error(
        fmt::format("cannot read image '{}': not a 2-D picture", path.string()));
  }
  const int channels = std::min(spec.nchannels, 3);
  std::vector<float> stored(std::size_t(spec.width) * std::size_t(spec.height) * channels);
  if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, stored.data())) {
    throw std::runtime_error(
        fmt::format("cannot read image '{}': {}", path.string(), input->geterror()));
  }
  RgbImage image(spec.width, spec.height);
  for (std::size_t i = 0; i < image.pixel_count(); ++i) {
    for (int c = 0; c < 3; ++c) {
      image.pixels[i * 3 + c] = stored[i * channels + (channels == 3 ? c : 0)];
    }
  }
  return image;
}

void write_png(const std::filesystem::path& path, const RgbImage& image,
               const std::string& description) {
  // Quantise here rather than leave it to OpenImageIO, so "rounded to nearest" is our contract.
  std::vector<std::uint8_t> bytes(image.pixels.size());
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    const float v = image.pixels[i] > 0.0f ? std::fmin(image.pixels[i], 1.0f) : 0.0f;
    bytes[i] = std::uint8_t(std::lround(v * 255.0f));
  }
  std::filesystem::path tmp = path;
  tmp += ".tmp.png";  // the real extension last: OpenImageIO picks the format from it
  auto output = OIIO::ImageOutput::create(tmp.string());
  OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:ColorSpace", "sRGB");
  // zlib level 1: measured 3.5x faster than OpenImageIO's default 6 on rendered frames (3.8 vs
  // 13.3 ms at 320x240) for files 1 % larger.
  spec.attribute("png:compressionLevel", 1);
  if (!description.empty()) spec.attribute("ImageDescription", description);
  const auto fail = [&](const std::string& reason) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    return std::runtime_error(fmt::format("cannot write image '{}': {}", path.string(), reason));
  };
  if (!output) throw fail(OIIO::geterror());
  if (!output->open(tmp.string(), spec) ||
      !output->write_image(OIIO::TypeDesc::UINT8, bytes.data()) || !output->close()) {
    throw fail(output->geterror());
  }
  std::error_code error;
  std::filesystem::rename(tmp, path, error);
  if (error) throw fail(error.message());
}

}  // namespace raintrace::film
