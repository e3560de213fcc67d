// Number text (see number_format.h).
#include "povgen/number_format.h"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace raintrace::povgen {
namespace {

/// Room for any number written here: a sign, 17 digits, a point, an exponent.
constexpr int kMaxChars = 32;

}  // namespace

void append_number(std::string& text, double value) {
  if (!std::isfinite(value)) {
    throw std::invalid_argument("cannot write a non-finite number (NaN or infinity) to POV-Ray");
  }
  if (value == 0.0) value = 0.0;  // -0 → 0: the bytes must not depend on the sign of a zero
  char digits[kMaxChars];
  const auto end =
      std::to_chars(digits, digits + kMaxChars, value, std::chars_format::general, 7).ptr;
  text.append(digits, end);
}

void append_fixed5(std::string& text, double value) {
  if (!(std::fabs(value) < 1e12)) {  // also NaN, which append_number refuses
    append_number(text, value);
    return;
  }
  const long long steps = std::llround(value * 1e5);  // multiples of 10 µm
  if (steps < 0) text += '-';
  const auto magnitude = static_cast<std::uint64_t>(steps < 0 ? -steps : steps);
  append_index(text, magnitude / 100000);
  std::uint64_t fraction = magnitude % 100000;
  if (fraction == 0) return;
  // Five decimals, zero-padded, then cut after the last one that is not zero.
  char decimals[6] = {'.', '0', '0', '0', '0', '0'};
  for (int i = 5; i >= 1; --i, fraction /= 10) decimals[i] = static_cast<char>('0' + fraction % 10);
  int length = 6;
  while (decimals[length - 1] == '0') --length;
  text.append(decimals, static_cast<std::size_t>(length));
}

void append_index(std::string& text, std::uint64_t value) {
  char digits[kMaxChars];
  text.append(digits, std::to_chars(digits, digits + kMaxChars, value).ptr);
}

std::string format_number(double value) {
  std::string text;
  append_number(text, value);
  return text;
}

}  // namespace raintrace::povgen
