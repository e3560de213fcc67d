// Words for ranges and numbers in messages (see param_table.h).
#include "sim/param_table.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace raintrace::sim {

std::string number_text(double value) {
  char text[64];
  const auto scientific =
      std::to_chars(text, text + sizeof text, value, std::chars_format::scientific);
  if (!std::isfinite(value)) return {text, scientific.ptr};
  // The shortest digits are the same in both forms; the exponent picks the form.
  const char* e = std::find(text, scientific.ptr, 'e');
  int exponent = 0;
  std::from_chars(e + (e[1] == '+' ? 2 : 1), scientific.ptr, exponent);
  if (exponent < -4 || exponent >= 16) return {text, scientific.ptr};
  const auto fixed = std::to_chars(text, text + sizeof text, value, std::chars_format::fixed);
  return {text, fixed.ptr};
}

std::string Range::describe() const {
  const bool has_min = std::isfinite(min);
  const bool has_max = std::isfinite(max);
  if (has_min && has_max) {
    return std::string{"in "} + (min_open ? '(' : '[') + number_text(min) + ", " +
           number_text(max) + (max_open ? ')' : ']');
  }
  if (has_min) return (min_open ? "> " : ">= ") + number_text(min);
  if (has_max) return (max_open ? "< " : "<= ") + number_text(max);
  return "finite";
}

}  // namespace raintrace::sim
