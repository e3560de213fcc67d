// Numbers as POV-Ray text: 7 significant digits, shortest form, no locale, no printf.
// POV-Ray spends ~1 µs parsing each number whatever its length (shared/POVRAY-NOTES.md), and
// 4 digits visibly move metre-scale geometry, so 7 digits is the floor and the ceiling.
#pragma once

#include <cstdint>
#include <string>

namespace raintrace::povgen {

/// Largest text append_number() can produce, in bytes.
inline constexpr int max_number_chars = 24;

/// Writes `value` with 7 significant digits, trailing zeros stripped, "-0" written as "0",
/// exponent form only outside [1e-3, 1e7). Returns the end of the text. Throws
/// std::invalid_argument for NaN or infinity: POV-Ray would read them as a parse error or, worse,
/// as an identifier. `out` must have max_number_chars bytes.
char* write_number(char* out, double value);

/// Writes a non-negative integer (mesh indices, frame numbers). Returns the end of the text.
char* write_index(char* out, std::uint64_t value);

/// Appends write_number(value) to text.
void append_number(std::string& text, double value);

/// The text write_number() produces, as a string: for tests and one-off values.
std::string format_number(double value);

}  // namespace raintrace::povgen
