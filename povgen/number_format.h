// Numbers as POV-Ray text. POV-Ray spends about a microsecond parsing a number whatever its
// length (docs/povray-notes.md), and 4 significant digits visibly move metre-scale geometry, so
// numbers get 7 significant digits; streak corners, where absolute precision is what matters,
// are written to 10 µm in fixed point. std::to_chars makes the digits: no locale, no printf,
// the same bytes everywhere.
//
// Each writer comes twice: write_*(first, last, value) writes into [first, last), checking
// the room first, and returns the end of the text (for frame_text.cpp, which makes a line at a
// time); append_*(text, value) appends to a string.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>

namespace raintrace::povgen {

/// Room any one number needs: a sign, 18 digits, a point, an exponent, with some to spare.
inline constexpr std::size_t kMaxNumberChars = 32;

/// `value` with 7 significant digits in its shortest form, "-0" as "0". From 1e-3 to 1e7
/// (every coordinate, radius and colour) that is the value rounded half away from zero to its
/// 7th digit, in fixed form without trailing zeros: std::to_chars(general, 7)'s text except
/// that an exact tie rounds away from zero (0.12890625 → 0.1289063) and 9999999.5 and above
/// give "10000000". Outside that range it is std::to_chars(general, 7) ("1e-05", "2.5e+09").
/// Throws std::invalid_argument for NaN or infinity (POV-Ray would read them as a parse error
/// or, worse, as an identifier) and std::length_error when [first, last) holds fewer than
/// kMaxNumberChars characters.
char* write_number(char* first, char* last, double value);

/// `value` rounded to a multiple of 10 µm (half away from zero) in fixed point: the shortest
/// text of the rounded value ("1.5", "-0.00002", "100"), "-0" as "0". For streak corners: a
/// streak is at least a pixel wide, and a pixel is far wider than 10 µm wherever a streak is
/// drawn (mesh2 keeps single precision anyway). From 10^12 on (and for NaN or infinity, which
/// it refuses) it is write_number(). Throws as write_number().
char* write_fixed5(char* first, char* last, double value);

/// A non-negative integer (mesh indices, frame numbers). Throws as write_number().
char* write_index(char* first, char* last, std::uint64_t value);

/// The same, appended to `text`.
void append_number(std::string& text, double value);
void append_fixed5(std::string& text, double value);
void append_index(std::string& text, std::uint64_t value);

/// The text append_number() appends, as a string: for one-off values and tests.
std::string format_number(double value);
/// A POV-Ray vector of three such numbers: "<x,y,z>".
std::string format_vector(const glm::dvec3& v);

}  // namespace raintrace::povgen
