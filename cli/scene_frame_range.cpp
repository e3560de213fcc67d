// `--frames A-B` parsing; see parse_frame_range in scene.h.
#include <fmt/core.h>
#include <charconv>
#include <stdexcept>
#include <string>

#include "cli/scene.h"
#include "cli/scene_error.h"

namespace raintrace::cli {
namespace {

/// A whole decimal number with nothing else around it; nullopt-like -1 when malformed.
long long parse_frame_number(std::string_view text) {
  long long value = -1;
  if (text.empty() || text.front() == '+' || text.front() == '-') return -1;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || end != text.data() + text.size()) return -1;
  return value;
}

}  // namespace

FrameRange parse_frame_range(std::string_view text, int frames) {
  if (frames < 1) throw std::invalid_argument("the scene has no frames");
  if (text.empty()) return {1, frames};
  const auto malformed = [&] {
    return std::invalid_argument(
        fmt::format("--frames: expected N or A-B with 1 <= A <= B <= {} (e.g. 1-{} or 5), got {}",
                    frames, frames, in_quotes(text)));
  };
  const std::size_t dash = text.find('-');
  const long long first = parse_frame_number(text.substr(0, dash));
  const long long last =
      dash == std::string_view::npos ? first : parse_frame_number(text.substr(dash + 1));
  if (first < 0 || last < 0) throw malformed();
  if (first > last) {
    throw std::invalid_argument(
        fmt::format("--frames: {} ends before it starts (A-B needs A <= B)", escaped(text)));
  }
  if (first < 1 || last > frames) {
    throw std::invalid_argument(
        fmt::format("--frames: {} is outside the scene's frames 1-{}", escaped(text), frames));
  }
  return {static_cast<int>(first), static_cast<int>(last)};
}

}  // namespace raintrace::cli
