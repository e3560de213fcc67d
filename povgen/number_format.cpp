// Fast 7-significant-digit formatting. The common case (|v| in [1e-3, 1e7), which covers every
// coordinate and radius raintrace writes) is rounded to an integer with the right number of
// decimals and written with a two-digit table; everything else goes through std::to_chars.
#include "povgen/number_format.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace raintrace::povgen {
namespace {

constexpr std::array<double, 10> kPow10{1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
constexpr std::array<std::uint64_t, 10> kPow10Int{1,      10,      100,      1000,      10000,
                                                  100000, 1000000, 10000000, 100000000, 1000000000};

constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

/// Writes exactly `width` digits of value (zero-padded on the left).
void write_padded(char* out, std::uint64_t value, int width) {
  char* p = out + width;
  while (value >= 100) {
    const auto pair = static_cast<unsigned>(value % 100) * 2;
    value /= 100;
    p -= 2;
    std::memcpy(p, kDigitPairs + pair, 2);
  }
  if (value >= 10) {
    p -= 2;
    std::memcpy(p, kDigitPairs + static_cast<unsigned>(value) * 2, 2);
  } else if (p > out || value > 0) {
    *--p = static_cast<char>('0' + value);
  }
  while (p > out) *--p = '0';
}

int digit_count(std::uint64_t value) {
  int n = 1;
  while (value >= 10) {
    value /= 10;
    ++n;
  }
  return n;
}

}  // namespace

char* write_index(char* out, std::uint64_t value) {
  const int n = digit_count(value);
  write_padded(out, value, n);
  return out + n;
}

char* write_number(char* out, double value) {
  if (!std::isfinite(value)) {
    throw std::invalid_argument("cannot write a non-finite number (NaN or infinity) to POV-Ray");
  }
  double magnitude = std::fabs(value);
  if (magnitude >= 1e-3 && magnitude < 1e7) {
    // Integer digits before the point decide how many decimals give 7 significant digits.
    int decimals = 6;
    if (magnitude < 1.0) {
      decimals = magnitude >= 0.1 ? 7 : (magnitude >= 0.01 ? 8 : 9);
    } else {
      int int_digits = 1;
      while (int_digits < 7 && magnitude >= kPow10[static_cast<std::size_t>(int_digits)]) {
        ++int_digits;
      }
      decimals = 7 - int_digits;
    }
    // Round half away from zero, as llround, without the libm call (magnitude > 0 here).
    auto scaled =
        static_cast<std::uint64_t>(magnitude * kPow10[static_cast<std::size_t>(decimals)] + 0.5);
    if (scaled == 0) {
      *out = '0';
      return out + 1;
    }
    // Strip trailing zeros of the fraction without changing the value.
    while (decimals > 0 && scaled % 10 == 0) {
      scaled /= 10;
      --decimals;
    }
    if (value < 0) *out++ = '-';
    const std::uint64_t unit = kPow10Int[static_cast<std::size_t>(decimals)];
    out = write_index(out, scaled / unit);
    if (decimals > 0) {
      *out++ = '.';
      write_padded(out, scaled % unit, decimals);
      out += decimals;
    }
    return out;
  }
  if (magnitude == 0.0) {
    *out = '0';
    return out + 1;
  }
  const auto result =
      std::to_chars(out, out + max_number_chars, value, std::chars_format::general, 7);
  return result.ptr;
}

void append_number(std::string& text, double value) {
  char buffer[max_number_chars];
  char* end = write_number(buffer, value);
  text.append(buffer, end);
}

std::string format_number(double value) {
  std::string text;
  append_number(text, value);
  return text;
}

}  // namespace raintrace::povgen
