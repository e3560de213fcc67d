// Fast 7-significant-digit formatting. The common case (|v| in [1e-3, 1e7), which covers every
// coordinate and radius raintrace writes) is rounded to an integer of at most 8 digits, written
// as 8 zero-padded digits with a two-digit table, and the point goes in between; everything
// else goes through std::to_chars. Text is written a word at a time and trimmed afterwards, so
// the hot path has no division loops and few data-dependent branches. write_fixed5() and
// write_index() are inline in the header; only their rare cases live here.
#include "povgen/number_format.h"

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace raintrace::povgen {
namespace {

using detail::eight_digits;
using detail::kZeroChars;
using detail::store_8;

constexpr std::array<double, 10> kPow10{1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};

/// Decimals that give 7 significant digits for magnitude in [1e-3, 1e7): 9 at 1e-3, one fewer
/// per power of ten, 0 from 1e6 on. Comparisons instead of a loop: no branch to mispredict.
int decimals_for(double magnitude) {
  return 9 - (magnitude >= 1e-2) - (magnitude >= 1e-1) - (magnitude >= 1e0) - (magnitude >= 1e1) -
         (magnitude >= 1e2) - (magnitude >= 1e3) - (magnitude >= 1e4) - (magnitude >= 1e5) -
         (magnitude >= 1e6);
}

/// write_number() for magnitude in [1e-3, 1e7).
char* write_fixed(char* out, double value, double magnitude) {
  const int decimals = decimals_for(magnitude);
  // Round half away from zero, as llround, without the libm call (magnitude > 0 here). At most
  // 10^7 (9999999.5 rounds up), so 8 digits always hold it.
  const auto scaled =
      static_cast<std::uint32_t>(magnitude * kPow10[static_cast<std::size_t>(decimals)] + 0.5);
  if (scaled == 0) {
    *out = '0';
    return out + 1;
  }
  const std::uint64_t digits = eight_digits(scaled);  // non-zero: scaled > 0
  const int leading_zeros = std::countr_zero(digits) / 8;
  const int trailing_zeros = std::countl_zero(digits) / 8;
  const std::uint64_t text = digits + kZeroChars;
  // Trailing zeros of the fraction are dropped, as the shortest form of the same value.
  const int fraction_length = std::max(decimals - trailing_zeros, 0);

  *out = '-';
  out += value < 0;
  std::uint64_t fraction = text;
  if (decimals >= 8) {
    // Below 0.1 all 8 digits are decimals, below 0.01 after one more zero.
    *out++ = '0';
    if (decimals == 9) fraction = (fraction << 8) | '0';
  } else {
    // Integer digits are those left of the last `decimals`; keep at least one.
    const int integer_begin = std::min(leading_zeros, 7 - decimals);
    store_8(out, text >> (8 * integer_begin));
    out += 8 - decimals - integer_begin;
    // (With no decimals there is no fraction, and a shift by 64 bits would be undefined.)
    if (decimals > 0) fraction = text >> (8 * (8 - decimals));
  }
  if (fraction_length > 0) {
    *out++ = '.';
    store_8(out, fraction);
    if (decimals == 9) out[8] = static_cast<char>(text >> 56);
    out += fraction_length;
  }
  return out;
}

}  // namespace

namespace detail {

char* write_fixed5_rare(char* out, double value, double magnitude) {
  // Also taken for NaN: non-finite values reach write_number(), which refuses them.
  if (!(magnitude < 1e12)) return write_number(out, value);
  // Round half away from zero, as the fast path; below 10^17 steps fit 64 bits.
  const auto steps = static_cast<std::uint64_t>(magnitude * 1e5 + 0.5);
  *out = '-';
  out += value < 0;
  out = write_index(out, steps / 100'000);
  const auto fraction = static_cast<std::uint32_t>(steps % 100'000);
  if (fraction == 0) return out;
  // The fraction's 5 digits are the last 5 of the eight: bytes 3..7 of the word.
  const std::uint64_t digits = eight_digits(fraction);
  *out++ = '.';
  store_8(out, (digits + kZeroChars) >> 24);
  return out + 5 - std::countl_zero(digits) / 8;
}

char* write_index_wide(char* out, std::uint64_t value) {
  return std::to_chars(out, out + max_number_chars, value).ptr;
}

}  // namespace detail

char* write_number(char* out, double value) {
  if (!std::isfinite(value)) {
    throw std::invalid_argument("cannot write a non-finite number (NaN or infinity) to POV-Ray");
  }
  const double magnitude = std::fabs(value);
  if (magnitude >= 1e-3 && magnitude < 1e7) return write_fixed(out, value, magnitude);
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
