// The develop pipeline (order and contracts in develop.h).
#include "film/develop.h"

#include <fmt/core.h>

#include <charconv>
#include <map>
#include <sstream>
#include <stdexcept>

#include "film/bloom.h"
#include "film/diffraction_spikes.h"
#include "film/exposure.h"
#include "film/grain.h"
#include "film/image_file.h"
#include "film/sensor_noise.h"
#include "film/softness.h"
#include "film/vignette.h"
#include "film/white_balance.h"

namespace raintrace::film {

namespace {

constexpr const char* kDescribed = "raintrace develop:";

void check_range(const char* name, double value, double lo, double hi) {
  if (!(value >= lo && value <= hi)) {
    throw std::invalid_argument(fmt::format("{} must be in [{}, {}], got {}", name, lo, hi, value));
  }
}

}  // namespace

void validate(const DevelopSettings& settings) {
  check_range("exposure_ev", settings.exposure_ev, -kExposureLimitEv, kExposureLimitEv);
  if (settings.white_balance_k != 0.0) {
    check_range("white_balance_k", settings.white_balance_k, kMinWhiteBalanceK, kMaxWhiteBalanceK);
  }
  check_range("bloom", settings.bloom, 0.0, 1.0);
  check_range("softness", settings.softness, 0.0, kMaxSoftness);
  check_range("grain", settings.grain, 0.0, kMaxGrain);
  check_range("sensor_noise", settings.sensor_noise, 0.0, kMaxSensorNoise);
  check_range("vignette", settings.vignette, 0.0, 1.0);
  if (!is_blade_count(settings.aperture_blades)) {
    throw std::invalid_argument(fmt::format("aperture_blades must be 0 or in [3, {}], got {}",
                                            kMaxApertureBlades, settings.aperture_blades));
  }
}

std::string describe(const DevelopSettings& settings) {
  const std::string look =
      settings.view == View::filmic ? fmt::format(" look={}", to_string(settings.look)) : "";
  // Keys added since pictures were first described are named only when on.
  const std::string balance = settings.white_balance_k != 0.0
                                  ? fmt::format(" white_balance_k={}", settings.white_balance_k)
                                  : "";
  const std::string softness =
      settings.softness != 0.0 ? fmt::format(" softness={}", settings.softness) : "";
  const std::string noise =
      settings.sensor_noise != 0.0 ? fmt::format(" sensor_noise={}", settings.sensor_noise) : "";
  const std::string blades = settings.aperture_blades != 0
                                 ? fmt::format(" aperture_blades={}", settings.aperture_blades)
                                 : "";
  return fmt::format("{} exposure_ev={}{} view={}{} bloom={}{} grain={}{} vignette={}{}",
                     kDescribed, settings.exposure_ev, balance, to_string(settings.view), look,
                     settings.bloom, softness, settings.grain, noise, settings.vignette, blades);
}

std::string describe(const DevelopSettings& settings, const FrameContext& frame) {
  const std::string aperture =
      settings.aperture_blades != 0 ? fmt::format(" aperture_m={}", frame.aperture_m) : "";
  return fmt::format("{} fov_deg={}{} seed={} frame={}", describe(settings), frame.fov_deg,
                     aperture, frame.seed, frame.frame);
}

std::optional<DevelopDescription> parse_description(std::string_view text) {
  if (!text.starts_with(kDescribed)) return std::nullopt;
  std::map<std::string, std::string, std::less<>> fields;
  std::istringstream words{std::string{text.substr(std::string_view{kDescribed}.size())}};
  std::string word;
  while (words >> word) {
    const auto eq = word.find('=');
    if (eq == std::string::npos) return std::nullopt;
    fields[word.substr(0, eq)] = word.substr(eq + 1);
  }
  const auto number = [&](const char* key, auto& out) {
    const auto it = fields.find(key);
    if (it == fields.end()) return false;
    const char* end = it->second.data() + it->second.size();
    return std::from_chars(it->second.data(), end, out).ptr == end;
  };
  DevelopDescription d;
  DevelopSettings& s = d.settings;
  const auto view = fields.contains("view") ? parse_view(fields["view"]) : std::nullopt;
  if (!view) return std::nullopt;
  s.view = *view;
  if (s.view == View::filmic) {
    const auto look = fields.contains("look") ? parse_look(fields["look"]) : std::nullopt;
    if (!look) return std::nullopt;
    s.look = *look;
  }
  if (!number("exposure_ev", s.exposure_ev) || !number("bloom", s.bloom) ||
      !number("grain", s.grain) || !number("vignette", s.vignette) ||
      !number("fov_deg", d.frame.fov_deg) || !number("seed", d.frame.seed) ||
      !number("frame", d.frame.frame)) {
    return std::nullopt;
  }
  for (const auto& [key, value] :
       {std::pair{"white_balance_k", &s.white_balance_k}, std::pair{"softness", &s.softness},
        std::pair{"sensor_noise", &s.sensor_noise}}) {
    if (fields.contains(key) && !number(key, *value)) return std::nullopt;
  }
  if (fields.contains("aperture_blades") &&
      (!number("aperture_blades", s.aperture_blades) || !number("aperture_m", d.frame.aperture_m) ||
       !(d.frame.aperture_m > 0.0))) {
    return std::nullopt;
  }
  try {
    validate(s);
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
  return d;
}

RgbImage develop(const RgbImage& linear, const DevelopSettings& settings, const FrameContext& frame,
                 const DisplayTransform& display) {
  validate(settings);
  RgbImage image = linear;
  apply_white_balance(image, settings.white_balance_k);
  apply_exposure(image, settings.exposure_ev);
  apply_vignette(image, settings.vignette, frame.fov_deg);
  apply_diffraction_spikes(image, {settings.aperture_blades, frame.aperture_m}, frame.fov_deg);
  apply_softness(image, settings.softness);
  image = bloom(image, settings.bloom);
  apply_sensor_noise(image, settings.sensor_noise, frame.seed, frame.frame);
  image = display.to_display(image, settings.view, settings.look);
  apply_grain(image, settings.grain, frame.seed, frame.frame);
  return image;
}

void develop_file(const std::filesystem::path& hdr_in, const std::filesystem::path& png_out,
                  const DevelopSettings& settings, const FrameContext& frame,
                  const DisplayTransform& display) {
  validate(settings);
  write_png(png_out, develop(read_rgb_image(hdr_in), settings, frame, display),
            describe(settings, frame));
}

}  // namespace raintrace::film
