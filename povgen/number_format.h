// Numbers as POV-Ray text: 7 significant digits, shortest form, no locale, no printf.
// POV-Ray spends ~1 µs parsing each number whatever its length (shared/POVRAY-NOTES.md), and
// 4 digits visibly move metre-scale geometry, so 7 digits is the floor and the ceiling.
#pragma once

#include <algorithm>
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
/// "shortest form, no printf noise" rule holds, at a few ns per number instead of ~13.
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

/// write_fixed5() from 1000 m on, and for non-finite values.
char* write_fixed5_rare(char* out, double value, double magnitude);
/// write_index() from 10^8 on.
char* write_index_wide(char* out, std::uint64_t value);

}  // namespace detail

inline char* write_fixed5(char* out, double value) {
  using namespace detail;
  const double magnitude = std::fabs(value);
  // Below 1000 m (also false for NaN) the rounded value has at most 8 digits.
  if (!(magnitude < 999.99999)) return write_fixed5_rare(out, value, magnitude);
  // Round half away from zero, as write_number() does, without the libm call.
  const auto steps = static_cast<std::uint32_t>(magnitude * 1e5 + 0.5);
  // Eight digits, one per byte: 3 integer digits then 5 decimals. Keep at least one integer
  // digit; write the point and all 5 decimals, then step back over trailing zeros (and over
  // the point when all decimals are zero). Zero is "0", for -0 and tiny negatives too.
  const std::uint64_t digits = eight_digits(steps);
  const int integer_begin = std::min(std::countr_zero(digits | (1ULL << 16)) / 8, 2);
  const int fraction_length = 5 - std::min(std::countl_zero(digits) / 8, 5);
  const std::uint64_t text = digits + kZeroChars;
  *out = '-';
  out += value < 0 && steps != 0;
  store_8(out, text >> (8 * integer_begin));
  out += 3 - integer_begin;
  *out = '.';
  out += fraction_length > 0;
  store_8(out, text >> 24);
  return out + fraction_length;
}

inline char* write_index(char* out, std::uint64_t value) {
  using namespace detail;
  if (value >= kEightDigits) return write_index_wide(out, value);
  const std::uint64_t digits = eight_digits(static_cast<std::uint32_t>(value));
  // At least one digit: "0" for zero.
  const int leading_zeros = std::countr_zero(digits | (1ULL << 56)) / 8;
  store_8(out, (digits + kZeroChars) >> (8 * leading_zeros));
  return out + 8 - leading_zeros;
}

/// Appends write_number(value) to text.
void append_number(std::string& text, double value);

/// The text write_number() produces, as a string: for tests and one-off values.
std::string format_number(double value);

}  // namespace raintrace::povgen
