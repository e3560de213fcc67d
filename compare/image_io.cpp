// OpenImageIO-backed image reading and writing.
#include "compare/image_io.h"

#include <fmt/core.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <cctype>
#include <set>
#include <stdexcept>
#include <string>
#include <system_error>

namespace raintrace::compare {

Image read_image(const std::filesystem::path& path) {
  // ImageInput directly (not ImageBuf/ImageCache): one read, no shared cache growing across
  // hundreds of frames, and the error message stays tied to this file.
  auto input = OIIO::ImageInput::open(path.string());
  if (!input) {
    throw std::runtime_error(
        fmt::format("cannot read image '{}': {}", path.string(), OIIO::geterror()));
  }
  const OIIO::ImageSpec& spec = input->spec();
  if (spec.depth > 1) {
    throw std::runtime_error(fmt::format("cannot compare volume image '{}'", path.string()));
  }
  Image image(spec.width, spec.height, spec.nchannels);
  image.channel_names = spec.channelnames;
  image.scene_linear = spec.format.is_floating_point();
  image.description = spec.get_string_attribute("ImageDescription");
  if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data())) {
    throw std::runtime_error(
        fmt::format("cannot read image '{}': {}", path.string(), input->geterror()));
  }
  input->close();
  return image;
}

void write_image(const std::filesystem::path& path, const Image& image) {
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  tmp += path.extension();  // keep the real extension last: OIIO picks the format from it
  auto output = OIIO::ImageOutput::create(tmp.string());
  if (!output) {
    throw std::runtime_error(
        fmt::format("cannot write image '{}': {}", path.string(), OIIO::geterror()));
  }
  const bool low_bit = path.extension() == ".png" || path.extension() == ".jpg";
  OIIO::ImageSpec spec(image.width, image.height, image.channels,
                       low_bit ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
  if (!output->open(tmp.string(), spec) ||
      !output->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data()) || !output->close()) {
    const std::string reason = output->geterror();
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw std::runtime_error(fmt::format("cannot write image '{}': {}", path.string(), reason));
  }
  std::filesystem::rename(tmp, path);
}

bool is_image_file(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  if (ext.size() < 2) return false;
  ext = ext.substr(1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return char(std::tolower(ch)); });
  static const auto extensions = [] {
    std::set<std::string> all;
    for (const auto& [format, exts] : OIIO::get_extension_map())
      all.insert(exts.begin(), exts.end());
    return all;
  }();
  return extensions.count(ext) > 0;
}

void set_oiio_threads(int threads) { OIIO::attribute("threads", threads); }

}  // namespace raintrace::compare
