// Filmic / Standard display transforms through OpenImageIO's OpenColorIO support.
#include "film/display_transform.h"

#include <fmt/core.h>

#include <OpenImageIO/color.h>
#include <algorithm>
#include <array>
#include <iterator>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace raintrace::film {

namespace {

/// The configuration's look names, in the order of Look (and kLookNames).
constexpr std::array<const char*, std::size(kLookNames)> kOcioLooks{
    "Very Low Contrast",    "Low Contrast",  "Medium Low Contrast", "Medium Contrast",
    "Medium High Contrast", "High Contrast", "Very High Contrast"};

/// The configuration's names this module relies on.
constexpr const char* kLinear = "Linear";
constexpr const char* kDisplay = "sRGB";

const char* ocio_view(View view) { return view == View::filmic ? "Filmic" : "Standard"; }

}  // namespace

std::string_view to_string(View view) { return kViewNames[std::size_t(view)]; }

std::string_view to_string(Look look) { return kLookNames[std::size_t(look)]; }

std::optional<View> parse_view(std::string_view text) {
  for (std::size_t i = 0; i < std::size(kViewNames); ++i) {
    if (kViewNames[i] == text) return View(i);
  }
  return std::nullopt;
}

std::optional<Look> parse_look(std::string_view text) {
  for (std::size_t i = 0; i < std::size(kLookNames); ++i) {
    if (kLookNames[i] == text) return Look(i);
  }
  return std::nullopt;
}

struct DisplayTransform::Impl {
  OIIO::ColorConfig config;
  /// One processor per view and per look, made once: OpenColorIO's CPU processors are
  /// immutable and may be applied from several threads at once.
  std::array<OIIO::ColorProcessorHandle, 2> views;
  std::array<OIIO::ColorProcessorHandle, kOcioLooks.size()> looks;

  explicit Impl(const std::string& path) : config(path) {}
};

DisplayTransform::DisplayTransform(const std::filesystem::path& config) {
  const std::string path = config.string();
  std::error_code ignored;
  if (!std::filesystem::is_regular_file(config, ignored)) {
    throw std::runtime_error(fmt::format(
        "Blender's colour configuration '{}' is missing: install the Debian package blender-data",
        path));
  }
  // OpenImageIO 2.4's ColorConfig(path) does not fail on a missing file: it records an error
  // and carries on without the configuration, so the file is checked first. Given a path it
  // never reads $OCIO, so the user's environment cannot change the pictures.
  m_impl = std::make_unique<Impl>(path);
  OIIO::ColorConfig& cc = m_impl->config;
  const auto need = [&](OIIO::ColorProcessorHandle handle, const std::string& what) {
    if (!handle) {
      const std::string reason = cc.geterror();
      throw std::runtime_error(
          fmt::format("'{}' is not Blender's Filmic colour configuration: {}{}", path, what,
                      reason.empty() ? "" : " (" + reason + ")"));
    }
    return handle;
  };
  for (View view : {View::filmic, View::standard}) {
    m_impl->views[std::size_t(view)] = need(
        cc.createDisplayTransform(kDisplay, ocio_view(view), kLinear),
        fmt::format("no view '{}' on display '{}' from '{}'", ocio_view(view), kDisplay, kLinear));
  }
  // OpenImageIO 2.4 with OpenColorIO 2 ignores the `looks` argument of display transforms
  // (ociodisplay only notes "looks overrides are not allowed"), so a look is its own transform
  // from Linear to Linear, applied before the view: what Blender does (the look, then the view
  // with its looks bypassed). medium-contrast is Filmic's base curve: no transform at all.
  const std::vector<std::string> names = cc.getLookNames();
  for (std::size_t i = 0; i < kOcioLooks.size(); ++i) {
    const char* ocio = kOcioLooks[i];
    const bool known = std::find(names.begin(), names.end(), ocio) != names.end();
    if (!known) need(nullptr, fmt::format("no look '{}'", ocio));
    if (Look(i) == Look::medium_contrast) continue;
    m_impl->looks[i] =
        need(cc.createLookTransform(ocio, kLinear, kLinear), fmt::format("look '{}'", ocio));
  }
}

DisplayTransform::~DisplayTransform() = default;

RgbImage DisplayTransform::to_display(const RgbImage& linear, View view, Look look) const {
  if (view == View::standard) look = Look::medium_contrast;  // looks are Filmic's
  RgbImage out = linear;
  if (out.pixel_count() == 0) return out;
  // In place on our own buffer, on the calling thread (OpenColorIO's CPU path is per pixel, so
  // the result does not depend on how a caller splits the work).
  const auto apply = [&out](const OIIO::ColorProcessorHandle& processor) {
    constexpr OIIO::stride_t channel = sizeof(float);
    processor->apply(out.pixels.data(), out.width, out.height, 3, channel, 3 * channel,
                     OIIO::stride_t(out.width) * 3 * channel);
  };
  if (look != Look::medium_contrast) apply(m_impl->looks[std::size_t(look)]);
  apply(m_impl->views[std::size_t(view)]);
  // Blender's Standard view extrapolates above 1 (its sRGB LUT reaches beyond white); a display
  // value is in [0, 1] whatever the view.
  for (float& v : out.pixels) v = std::clamp(v, 0.0f, 1.0f);
  return out;
}

RgbImage DisplayTransform::response(View view, Look look) const {
  constexpr std::array<float, 12> kLevels{0.0f, 1e-4f, 1e-3f, 0.01f, 0.05f, 0.18f,
                                          0.5f, 1.0f,  2.0f,  4.0f,  16.0f, 100.0f};
  constexpr int n = int(kLevels.size());
  RgbImage probe(n * n, n);
  for (int r = 0; r < n; ++r) {
    for (int g = 0; g < n; ++g) {
      for (int b = 0; b < n; ++b) {
        const int x = r * n + g;
        probe.at(x, b, 0) = kLevels[std::size_t(r)];
        probe.at(x, b, 1) = kLevels[std::size_t(g)];
        probe.at(x, b, 2) = kLevels[std::size_t(b)];
      }
    }
  }
  return to_display(probe, view, look);
}

}  // namespace raintrace::film
