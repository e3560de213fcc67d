// The develop pipeline (order and contracts in develop.h).
#include "film/develop.h"

#include <fmt/core.h>

#include <stdexcept>

#include "film/bloom.h"
#include "film/exposure.h"
#include "film/grain.h"
#include "film/image_file.h"
#include "film/vignette.h"

namespace raintrace::film {

namespace {

void check_range(const char* name, double value, double lo, double hi) {
  if (!(value >= lo && value <= hi)) {
    throw std::invalid_argument(fmt::format("{} must be in [{}, {}], got {}", name, lo, hi, value));
  }
}

}  // namespace

void validate(const DevelopSettings& settings) {
  check_range("exposure_ev", settings.exposure_ev, -kExposureLimitEv, kExposureLimitEv);
  check_range("bloom", settings.bloom, 0.0, 1.0);
  check_range("grain", settings.grain, 0.0, kMaxGrain);
  check_range("vignette", settings.vignette, 0.0, 1.0);
  if (settings.view == View::standard && settings.look != Look::medium_contrast) {
    throw std::invalid_argument(
        fmt::format("look '{}' needs view 'filmic'", to_string(settings.look)));
  }
}

std::string describe(const DevelopSettings& settings) {
  return fmt::format(
      "raintrace develop: exposure_ev={} view={} look={} bloom={} grain={} vignette={}",
      settings.exposure_ev, to_string(settings.view), to_string(settings.look), settings.bloom,
      settings.grain, settings.vignette);
}

RgbImage develop(const RgbImage& linear, const DevelopSettings& settings, const FrameContext& frame,
                 const DisplayTransform& display) {
  validate(settings);
  RgbImage image = linear;
  apply_exposure(image, settings.exposure_ev);
  apply_vignette(image, settings.vignette, frame.fov_deg);
  image = bloom(image, settings.bloom);
  image = display.to_display(image, settings.view, settings.look);
  apply_grain(image, settings.grain, frame.seed, frame.frame);
  return image;
}

void develop_file(const std::filesystem::path& hdr_in, const std::filesystem::path& png_out,
                  const DevelopSettings& settings, const FrameContext& frame,
                  const DisplayTransform& display) {
  validate(settings);
  write_png(png_out, develop(read_rgb_image(hdr_in), settings, frame, display), describe(settings));
}

}  // namespace raintrace::film
