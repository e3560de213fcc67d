// Number text (see number_format.h). Both number writers round the value to an integer count
// of its last digit's unit and let std::to_chars write that integer; the decimal point is put
// back in front of the last `decimals` digits.
#include "povgen/number_format.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace raintrace::povgen {
namespace {

/// 10^0 … 10^9, exact.
constexpr std::array<double, 10> kScale{1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
/// Where a value gains an integer digit and so needs one decimal fewer, from 1e-2 to 1e6.
constexpr std::array<double, 9> kDecades{1e-2, 1e-1, 1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6};

void require_room(const char* first, const char* last) {
  if (last - first < static_cast<std::ptrdiff_t>(kMaxNumberChars)) {
    throw std::length_error("number text: fewer than kMaxNumberChars characters of room");
  }
}

/// ±count / 10^decimals in its shortest fixed form ("0.00123" for 123 and 5, "12" for 1200
/// and 2), with a minus sign only when count is not zero. decimals <= 9; the text is made in a
/// local buffer (std::to_chars is given its end) and copied to `first`.
char* write_scaled(char* first, bool negative, std::uint64_t count, int decimals) {
  char buffer[kMaxNumberChars];
  char* begin = buffer + 12;  // room in front for zeros, the shifted integer part and a sign
  char* const last = std::to_chars(begin, buffer + kMaxNumberChars, count).ptr;
  while (last - begin <= decimals) *--begin = '0';  // at least one digit before the point
  char* const point = last - decimals;
  char* end = last;
  while (end > point && end[-1] == '0') --end;  // trailing zeros of the fraction
  // Move the integer digits one to the left and put the point where the last one was; without
  // a fraction, no point.
  std::copy(begin, point, begin - 1);
  --begin;
  point[-1] = '.';
  if (end == point) end = point - 1;
  if (negative && count != 0) *--begin = '-';
  return std::copy(begin, end, first);
}

/// Rounds a magnitude (>= 0) half away from zero to an integer: the rule of every number text
/// since the first reference stills.
std::uint64_t rounded(double magnitude) { return static_cast<std::uint64_t>(magnitude + 0.5); }

}  // namespace

char* write_number(char* first, char* last, double value) {
  require_room(first, last);
  if (!std::isfinite(value)) {
    throw std::invalid_argument("cannot write a non-finite number (NaN or infinity) to POV-Ray");
  }
  const double magnitude = std::fabs(value);
  if (magnitude >= 1e-3 && magnitude < 1e7) {
    // Every coordinate, radius and colour raintrace writes: 9 decimals in [1e-3, 1e-2), one
    // fewer for each decade above, so that 7 significant digits remain.
    int decimals = 9;
    for (const double decade : kDecades) decimals -= magnitude >= decade ? 1 : 0;
    return write_scaled(first, value < 0,
                        rounded(magnitude * kScale[static_cast<std::size_t>(decimals)]), decimals);
  }
  if (magnitude == 0.0) {  // also -0: the bytes must not depend on the sign of a zero
    *first = '0';
    return first + 1;
  }
  return std::to_chars(first, last, value, std::chars_format::general, 7).ptr;
}

char* write_fixed5(char* first, char* last, double value) {
  const double magnitude = std::fabs(value);
  if (!(magnitude < 1e12)) return write_number(first, last, value);  // also NaN: refused there
  require_room(first, last);
  return write_scaled(first, value < 0, rounded(magnitude * 1e5), 5);  // in steps of 10 µm
}

char* write_index(char* first, char* last, std::uint64_t value) {
  require_room(first, last);
  return std::to_chars(first, last, value).ptr;
}

void append_number(std::string& text, double value) {
  char digits[kMaxNumberChars];
  text.append(digits, write_number(digits, digits + kMaxNumberChars, value));
}

void append_fixed5(std::string& text, double value) {
  char digits[kMaxNumberChars];
  text.append(digits, write_fixed5(digits, digits + kMaxNumberChars, value));
}

void append_index(std::string& text, std::uint64_t value) {
  char digits[kMaxNumberChars];
  text.append(digits, write_index(digits, digits + kMaxNumberChars, value));
}

std::string format_number(double value) {
  std::string text;
  append_number(text, value);
  return text;
}

std::string format_vector(const glm::dvec3& v) {
  return "<" + format_number(v.x) + "," + format_number(v.y) + "," + format_number(v.z) + ">";
}

}  // namespace raintrace::povgen
