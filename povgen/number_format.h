// Numbers as POV-Ray text: 7 significant digits, shortest form, no locale, no printf.
// POV-Ray spends ~1 µs parsing each number whatever its length (docs/povray-notes.md), and
// 4 digits visibly move metre-scale geometry, so 7 digits is the floor and the ceiling.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

namespace raintrace::povgen {

/// Largest text append_number() can produce, in bytes.
inline constexpr int max_number_chars = 24;

/// Writes `value` with 7 significant digits, trailing zeros stripped, "-0" written as "0",
/// exponent form only outside [1e-3, 1e7). Returns the end of the text. Throws
/// std::invalid_argument for NaN or infinity: POV-Ray would read them as a parse error or, worse,
/// as an identifier. `out` must have max_number_chars bytes.
char* write_number(char* out, double value);

/// Step of write_fixed5(): 10 µm. A streak quad is at least a pixel wide, and a pixel is far
/// wider than 10 µm at any distance a streak is drawn; mesh2 keeps single precision anyway.
inline constexpr double fixed5_step = 1e-5;

/// Writes `value` rounded to a multiple of fixed5_step (half away from zero) in fixed point:
/// the integer of steps with the decimal point put in, trailing zeros of the fraction and the
/// point itself dropped when nothing follows, "-0" written as "0". That is exactly the shortest
/// fixed-form text that round-trips the rounded value (std::to_chars(fixed) of it), so the
/// "shortest form, no printf noise" rule holds, at ~4.5 ns per number instead of ~13: the
/// integer part and the decimals in groups of 2 and 3 come from tables (9 KB, built at compile
/// time) that also hold each piece's length with trailing zeros dropped.
/// For streak corners, where absolute precision is what matters; write_number() keeps relative
/// precision for everything else. Beyond 10^12 m it falls back to write_number(), which also
/// throws std::invalid_argument for NaN or infinity. `out` must have max_number_chars bytes.
char* write_fixed5(char* out, double value);

/// Writes a non-negative integer (mesh indices, frame numbers). Returns the end of the text.
char* write_index(char* out, std::uint64_t value);

// The two writers above run a dozen times per streak: they are inline, with their rare cases
// out of line in number_format.cpp.
namespace detail {

// Leading and trailing zeros are counted on the digits loaded as one little-endian word.
static_assert(std::endian::native == std::endian::little, "digit scans assume little-endian");

/// "00000000": added to eight digit values 0..9, one per byte, it makes them text.
inline constexpr std::uint64_t kZeroChars = 0x3030303030303030ULL;
inline constexpr std::uint32_t kEightDigits = 100'000'000;

/// The 8 decimal digits of value (< 10^8), zero-padded, one digit value (not yet a character)
/// per byte, most significant digit in the lowest byte, so that storing the word writes them
/// in reading order. SIMD within a register: both halves, then all four pairs, are split at
/// once with multiply-shift divisions, with no table and no loop. A zero digit is a zero byte,
/// so leading and trailing zeros are counted with countr_zero / countl_zero.
inline std::uint64_t eight_digits(std::uint32_t value) {
  // Two 32-bit lanes of 4 digits: x/100 == (x * 10486) >> 20 for x < 43699.
  const std::uint64_t quads = (value / 10000) | (static_cast<std::uint64_t>(value % 10000) << 32);
  const std::uint64_t hundreds = ((quads * 10486) >> 20) & 0x0000007F0000007FULL;
  // Four 16-bit lanes of 2 digits: x/10 == (x * 103) >> 10 for x < 179.
  const std::uint64_t pairs = hundreds | ((quads - hundreds * 100) << 16);
  const std::uint64_t tens = ((pairs * 103) >> 10) & 0x000F000F000F000FULL;
  return tens | ((pairs - tens * 10) << 8);
}

/// Stores the 8 bytes of word at out: one store, whatever part of it ends up being used.
inline void store_8(char* out, std::uint64_t word) { std::memcpy(out, &word, 8); }

/// The text of an integer below 10^8 in the low bytes of a word (reading order), and its length.
struct IndexText {
  std::uint64_t text;
  int length;
  /// The text of the value + k, for k ≤ 9 − its last digit: only the last character changes.
  [[nodiscard]] std::uint64_t plus(std::uint64_t k) const {
    return text + (k << (8 * (length - 1)));
  }
};

/// The text write_index() writes for value < 10^8, as a word: at least one digit ("0" for 0).
inline IndexText index_text(std::uint32_t value) {
  const std::uint64_t digits = eight_digits(value);
  const int leading_zeros = std::countr_zero(digits | (1ULL << 56)) / 8;
  return {(digits + kZeroChars) >> (8 * leading_zeros), 8 - leading_zeros};
}

/// Text pieces for write_fixed5(): each entry holds up to 3 characters in its low bytes (in
/// reading order) and a length in its top byte.
struct Fixed5Tables {
  /// i without leading zeros; length 1..3.
  std::array<std::uint32_t, 1000> integer{};
  /// The first 2 decimals, i zero-padded; length of ".hh" without trailing zeros, 0 for 0.
  std::array<std::uint32_t, 100> high{};
  /// The last 3 decimals, i zero-padded; length of ".hhlll" without trailing zeros, 0 for 0
  /// (then high's length applies).
  std::array<std::uint32_t, 1000> low{};
};

/// Up to `width` digits of i, zero-padded to `width` when width > 0 (none for width 0 = as
/// many as i needs), in the low bytes; `length` in the top byte.
constexpr std::uint32_t digit_text(std::uint32_t i, int width, std::uint32_t length) {
  std::uint32_t text = 0;
  int digits = width;
  if (digits == 0) digits = i >= 100 ? 3 : i >= 10 ? 2 : 1;
  for (int d = digits - 1; d >= 0; --d, i /= 10) text |= ('0' + i % 10) << (8 * d);
  return text | length << 24;
}

/// Decimals left of the last non-zero one, plus it: "120" → 2, "000" → 0.
constexpr std::uint32_t significant(std::uint32_t i, std::uint32_t width) {
  if (i == 0) return 0;
  while (i % 10 == 0) {
    i /= 10;
    --width;
  }
  return width;
}

constexpr Fixed5Tables make_fixed5_tables() {
  Fixed5Tables t;
  for (std::uint32_t i = 0; i < 1000; ++i) {
    const std::uint32_t digits = i >= 100 ? 3 : i >= 10 ? 2 : 1;
    t.integer[i] = digit_text(i, 0, digits);
    t.low[i] = digit_text(i, 3, i == 0 ? 0 : 3 + significant(i, 3));
  }
  for (std::uint32_t i = 0; i < 100; ++i) {
    t.high[i] = digit_text(i, 2, i == 0 ? 0 : 1 + significant(i, 2));
  }
  return t;
}

inline constexpr Fixed5Tables kFixed5 = make_fixed5_tables();

/// write_fixed5() from 1000 m on, and for non-finite values.
char* write_fixed5_rare(char* out, double value, double magnitude);
/// write_index() from 10^8 on.
char* write_index_wide(char* out, std::uint64_t value);

}  // namespace detail

inline char* write_fixed5(char* out, double value) {
  using namespace detail;
  const double magnitude = std::fabs(value);
  // Below 1000 m (also false for NaN) the rounded value has at most 3 integer digits.
  if (!(magnitude < 999.99999)) return write_fixed5_rare(out, value, magnitude);
  // Round half away from zero, as write_number() does, without the libm call.
  const auto steps = static_cast<std::uint32_t>(magnitude * 1e5 + 0.5);
  // steps = integer·10^5 + high·10^3 + low: three table look-ups give the text and lengths.
  const std::uint32_t integer = steps / 100'000;
  const std::uint32_t fraction = steps - integer * 100'000;
  const std::uint32_t high = fraction / 1000;
  const std::uint32_t low = fraction - high * 1000;
  const std::uint32_t integer_text = kFixed5.integer[integer];
  const std::uint32_t high_text = kFixed5.high[high];
  const std::uint32_t low_text = kFixed5.low[low];
  *out = '-';
  out += value < 0 && steps != 0;  // never "-0"
  std::memcpy(out, &integer_text, 4);
  out += integer_text >> 24;
  // ".hhlll", then cut after the last non-zero decimal (nothing at all when both are zero).
  const std::uint64_t decimals = '.' | static_cast<std::uint64_t>(high_text & 0xFFFF) << 8 |
                                 static_cast<std::uint64_t>(low_text & 0xFFFFFF) << 24;
  store_8(out, decimals);
  const std::uint32_t low_length = low_text >> 24;
  return out + (low_length != 0 ? low_length : high_text >> 24);
}

inline char* write_index(char* out, std::uint64_t value) {
  using namespace detail;
  if (value >= kEightDigits) return write_index_wide(out, value);
  const IndexText text = index_text(static_cast<std::uint32_t>(value));
  store_8(out, text.text);
  return out + text.length;
}

/// Appends write_number(value) to text.
void append_number(std::string& text, double value);

/// The text write_number() produces, as a string: for tests and one-off values.
std::string format_number(double value);

}  // namespace raintrace::povgen
