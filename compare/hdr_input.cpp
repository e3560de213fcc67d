// Scene-linear input → display values through film/ (rules in hdr_input.h).
#include "compare/hdr_input.h"

#include <fmt/core.h>
#include <stdexcept>
#include <utility>

namespace raintrace::compare {
namespace {

film::RgbImage to_rgb(const Image& image) {
  film::RgbImage rgb(image.width, image.height);
  const int c = image.channels;
  for (std::size_t i = 0; i < image.pixel_count(); ++i) {
    for (int k = 0; k < 3; ++k) {
      // One or two channels are grey (and alpha): the first channel three times.
      rgb.pixels[i * 3 + std::size_t(k)] = image.pixels[i * std::size_t(c) + (c >= 3 ? k : 0)];
    }
  }
  return rgb;
}

Image from_rgb(const film::RgbImage& rgb, const std::string& description) {
  Image image(rgb.width, rgb.height, 3);
  image.channel_names = {"R", "G", "B"};
  image.pixels = rgb.pixels;
  image.description = description;
  return image;
}

}  // namespace

HdrInput::HdrInput(HdrOptions options) : m_options{std::move(options)} {
  film::validate(m_options.curve);
}

HdrInput::~HdrInput() = default;

const film::DisplayTransform& HdrInput::display() {
  const std::lock_guard lock{m_mutex};
  if (!m_display) m_display = std::make_unique<film::DisplayTransform>();
  return *m_display;
}

std::string HdrInput::prepare(Image& image, const Image* partner) {
  if (!image.scene_linear) return "";
  if (m_options.linear) {
    if (partner != nullptr && !partner->scene_linear) {
      throw std::runtime_error(
          "--linear compares scene-linear values, but only one of the two images holds them "
          "(the other is a display picture): leave out --linear to develop the HDR one");
    }
    return "";
  }
  film::DevelopSettings settings = m_options.curve;
  film::FrameContext frame;
  if (partner != nullptr && !partner->scene_linear) {
    if (const auto d = film::parse_description(partner->description)) {
      settings = d->settings;
      frame = d->frame;
    }
  }
  const std::string how = film::describe(settings, frame);
  image = from_rgb(film::develop(to_rgb(image), settings, frame, display()), how);
  return how;
}

}  // namespace raintrace::compare
