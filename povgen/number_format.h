// Numbers as POV-Ray text. POV-Ray spends about a microsecond parsing a number whatever its
// length (docs/povray-notes.md), and 4 significant digits visibly move metre-scale geometry, so
// numbers get 7 significant digits; streak corners, where absolute precision is what matters,
// are written to 10 µm in fixed point. std::to_chars makes the digits: no locale, no printf,
// the same bytes everywhere. Each writer appends to a std::string, which checks every bound.
#pragma once

#include <cstdint>
#include <string>

namespace raintrace::povgen {

/// Appends `value` with 7 significant digits in its shortest form, as std::to_chars(general, 7)
/// writes it (trailing zeros dropped, exponent form below 1e-4 and from 1e7 on), "-0" as "0".
/// Throws std::invalid_argument for NaN or infinity: POV-Ray would read them as a parse error
/// or, worse, as an identifier.
void append_number(std::string& text, double value);

/// Appends `value` rounded to a multiple of 10 µm (half away from zero, as std::llround) in fixed
/// point: the shortest text of the rounded value ("1.5", "-0.00002", "100"), "-0" as "0". For
/// streak corners: a streak is at least a pixel wide, and a pixel is far wider than 10 µm
/// wherever a streak is drawn (mesh2 keeps single precision anyway). From 10^12 on (and for
/// NaN or infinity, which it refuses) it is append_number().
void append_fixed5(std::string& text, double value);

/// Appends a non-negative integer (mesh indices, frame numbers).
void append_index(std::string& text, std::uint64_t value);

/// The text append_number() appends, as a string: for one-off values and tests.
std::string format_number(double value);

}  // namespace raintrace::povgen
