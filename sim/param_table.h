// Parameter tables: a params struct's scene-file keys as data. One row per key names its
// section and key, its type, unit and valid range, and points at the struct field that holds
// it; the field's default member value is the key's default. Everything that needs to know a
// key reads its row: the scene reader (cli/scene.cpp), the checks of params built in code
// (sim::validate, povgen::validate) and the type/unit/default/range columns of
// docs/scene-format.md (cli/scene_format_doc.cpp, checked by a test). So a range is written
// once. Like Mitsuba's parameter table at the top of a plugin, each table sits right below its
// struct: sim/params.h, sim/camera.h, povgen/export_params.h, cli/scene.h.
//
// Adding a key is one field with its default plus one row (docs/contributing.md shows how):
//   double gust_period_s = 2.0;   // in the struct
//   number("wind", "gust_period_s", &WindParams::gust_period_s, "s", Range::open_closed(0, 60)),
//
// Pure data and constexpr helpers: no I/O, no TOML, no formatting library.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

namespace raintrace::sim {

/// The valid values of a number: [min, max], each end closed, open or infinite (no bound).
/// NaN is never contained.
struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  ///< min itself is excluded
  bool max_open = false;  ///< max itself is excluded

  static constexpr Range closed(double lo, double hi) { return {lo, hi, false, false}; }
  static constexpr Range open_closed(double lo, double hi) { return {lo, hi, true, false}; }
  static constexpr Range open(double lo, double hi) { return {lo, hi, true, true}; }
  static constexpr Range at_least(double lo) {
    return {lo, std::numeric_limits<double>::infinity(), false, false};
  }
  static constexpr Range at_most(double hi) {
    return {-std::numeric_limits<double>::infinity(), hi, false, false};
  }
  static constexpr Range any() { return {}; }

  [[nodiscard]] constexpr bool contains(double value) const {
    const bool above_min = min_open ? value > min : value >= min;
    const bool below_max = max_open ? value < max : value <= max;
    return above_min && below_max;
  }
  /// The words after "must be": "in [0, 500]", "in (0, 240]", ">= 0", "<= 1000000", "finite".
  [[nodiscard]] std::string describe() const;
};

/// A number as fmt's "{}" writes it: the shortest text that reads back to the same double,
/// in fixed form from 1e-4 up to 1e16 ("0.0001", "100000"), else with an exponent ("1e-05").
/// Used for every number in a message, so the reader and the checks word values alike.
std::string number_text(double value);

/// What kind of value a key takes (the docs' type column follows it).
enum class ParamType {
  number,   ///< a double (integers are accepted and converted)
  integer,  ///< an int
  seed,     ///< a std::uint64_t from a non-negative TOML integer: [0, 2^63 − 1]
  boolean,
  vector,  ///< glm::dvec3 from [x, y, z]; `range` applies to each component
  colour,  ///< a vector with each component in [0, 1] (linear RGB)
  choice,  ///< one of a few strings, stored as an enum or a string
  text,    ///< any string; what it may contain is checked where it is used
};

/// A field that takes one of `names`.
template <class P>
struct ChoiceField {
  std::span<const std::string_view> names;
  /// The index of the field's value in names (names.size() when it is none of them).
  std::size_t (*get)(const P&, std::span<const std::string_view> names);
  /// Stores the value that names[index] stands for.
  void (*set)(P&, std::span<const std::string_view> names, std::size_t index);
};

/// A field of P, by type.
template <class P>
using FieldOf = std::variant<double P::*, int P::*, std::uint64_t P::*, bool P::*, glm::dvec3 P::*,
                             std::string P::*, ChoiceField<P>>;

/// How a key must compare with another key of the same struct.
enum class Order {
  none,
  at_most,      ///< value <= other's value
  greater_than  ///< value > other's value
};

/// One key of a scene-file section, bound to one field of the params struct P.
template <class P>
struct Param {
  std::string_view section;  ///< "rain"; "" for the top level
  std::string_view key;      ///< "rate_mm_per_h"
  ParamType type = ParamType::number;
  FieldOf<P> field;
  std::string_view unit;        ///< "mm/h"; empty when the value has none
  Range range = Range::any();   ///< numbers, integers, and each component of a vector
  Order order = Order::none;    ///< a rule against another key of the same table…
  std::string_view other;       ///< …this one
  std::string_view note;        ///< further conditions, for the docs' range column
  std::string_view unset_name;  ///< when set, the field's default means "not set": the
                                ///< checks skip it and the docs show this word
  /// The same row with "value <= other's value" (checked once both are read).
  [[nodiscard]] constexpr Param at_most(std::string_view other_key) const {
    Param p = *this;
    p.order = Order::at_most;
    p.other = other_key;
    return p;
  }
  /// The same row with "value > other's value".
  [[nodiscard]] constexpr Param greater_than(std::string_view other_key) const {
    Param p = *this;
    p.order = Order::greater_than;
    p.other = other_key;
    return p;
  }
  /// The same row with words for the docs' range column (a rule checked in code).
  [[nodiscard]] constexpr Param with_note(std::string_view words) const {
    Param p = *this;
    p.note = words;
    return p;
  }
  /// The same row, its default standing for "not set" (shown as `word` in the docs).
  [[nodiscard]] constexpr Param unset_as(std::string_view word) const {
    Param p = *this;
    p.unset_name = word;
    return p;
  }
};

// Builders, one per type, so a table reads as a list of keys.

/// A row with the common cells filled (the builders below give the type).
template <class P>
constexpr Param<P> make_param(std::string_view section, std::string_view key, ParamType type,
                              FieldOf<P> field, std::string_view unit = {},
                              Range range = Range::any()) {
  Param<P> row{};
  row.section = section;
  row.key = key;
  row.type = type;
  row.field = field;
  row.unit = unit;
  row.range = range;
  return row;
}

template <class P>
constexpr Param<P> number(std::string_view section, std::string_view key, double P::*field,
                          std::string_view unit, Range range) {
  return make_param<P>(section, key, ParamType::number, field, unit, range);
}

template <class P>
constexpr Param<P> integer(std::string_view section, std::string_view key, int P::*field,
                           std::string_view unit, int min, int max) {
  return make_param<P>(section, key, ParamType::integer, field, unit, Range::closed(min, max));
}

template <class P>
constexpr Param<P> seed(std::string_view section, std::string_view key, std::uint64_t P::*field) {
  return make_param<P>(section, key, ParamType::seed, field, {},
                       Range::closed(0, 9223372036854775807.0));
}

template <class P>
constexpr Param<P> flag(std::string_view section, std::string_view key, bool P::*field) {
  return make_param<P>(section, key, ParamType::boolean, field);
}

template <class P>
constexpr Param<P> vector(std::string_view section, std::string_view key, glm::dvec3 P::*field,
                          std::string_view unit, Range each) {
  return make_param<P>(section, key, ParamType::vector, field, unit, each);
}

template <class P>
constexpr Param<P> colour(std::string_view section, std::string_view key, glm::dvec3 P::*field) {
  return make_param<P>(section, key, ParamType::colour, field, {}, Range::closed(0.0, 1.0));
}

template <class P>
constexpr Param<P> text(std::string_view section, std::string_view key, std::string P::*field) {
  return make_param<P>(section, key, ParamType::text, field);
}

namespace detail {
template <class M>
struct MemberOf;
template <class P, class T>
struct MemberOf<T P::*> {
  using Struct = P;
  using Type = T;
};
}  // namespace detail

/// A key that takes one of `names`. The field is an enum whose values are 0, 1, … in the
/// order of `names`, or a std::string that stores the name itself.
template <auto kField>
constexpr auto choice(std::string_view section, std::string_view key,
                      std::span<const std::string_view> names) {
  using P = typename detail::MemberOf<decltype(kField)>::Struct;
  using T = typename detail::MemberOf<decltype(kField)>::Type;
  ChoiceField<P> field{names, nullptr, nullptr};
  if constexpr (std::is_enum_v<T>) {
    field.get = [](const P& p, std::span<const std::string_view>) {
      return static_cast<std::size_t>(p.*kField);
    };
    field.set = [](P& p, std::span<const std::string_view>, std::size_t i) {
      p.*kField = static_cast<T>(i);
    };
  } else {
    static_assert(std::is_same_v<T, std::string>, "a choice is stored as an enum or a string");
    field.get = [](const P& p, std::span<const std::string_view> all) {
      std::size_t i = 0;
      while (i < all.size() && all[i] != p.*kField) ++i;
      return i;
    };
    field.set = [](P& p, std::span<const std::string_view> all, std::size_t i) {
      p.*kField = std::string{all[i]};
    };
  }
  return make_param<P>(section, key, ParamType::choice, field);
}

/// The row of `key` in `section`, or nullptr.
template <class P>
constexpr const Param<P>* find_param(std::span<const Param<P>> table, std::string_view section,
                                     std::string_view key) {
  for (const Param<P>& row : table) {
    if (row.section == section && row.key == key) return &row;
  }
  return nullptr;
}

/// True when every key is unique in its section and every order rule names a number row of
/// the same section: each table static_asserts it, so a mistyped rule does not compile.
template <class P>
constexpr bool well_formed(std::span<const Param<P>> table) {
  for (std::size_t i = 0; i < table.size(); ++i) {
    const Param<P>& row = table[i];
    for (std::size_t j = 0; j < i; ++j) {
      if (table[j].section == row.section && table[j].key == row.key) return false;
    }
    if (row.order == Order::none) continue;
    // Compared by index, not by pointer: GCC's UBSan instruments pointer comparisons, which
    // then stop being constant expressions and the static_assert no longer compiles.
    std::size_t other = 0;
    while (other < table.size() &&
           !(table[other].section == row.section && table[other].key == row.other)) {
      ++other;
    }
    if (other == table.size() || other == i || table[other].type != ParamType::number ||
        row.type != ParamType::number) {
      return false;
    }
  }
  return true;
}

/// "rain.rate_mm_per_h", or "seed" at the top level.
inline std::string full_key(std::string_view section, std::string_view key) {
  return section.empty() ? std::string{key} : std::string{section} + "." + std::string{key};
}

/// The value of a number row's field.
template <class P>
double number_value(const Param<P>& row, const P& object) {
  return object.*std::get<double P::*>(row.field);
}

/// Whether an order rule holds for two values, and the words of its failure: "<=" and ">" for
/// Order::at_most ("must be <= …, got 7 > 6"), ">" and "<=" for Order::greater_than.
struct OrderWords {
  bool holds;
  std::string_view wanted;
  std::string_view got;
};
constexpr OrderWords order_words(Order order, double value, double other) {
  if (order == Order::at_most) return {value <= other, "<=", ">"};
  return {value > other, ">", "<="};
}

/// Throws std::invalid_argument naming the first field of `object` that breaks its row: out of
/// range, not one of its choices, or against its order rule, e.g.
/// "rain.rate_mm_per_h must be in [0, 500] (got 600)" or
/// "rain.far_m must be > rain.near_m (got 0.2 <= 0.3)". For params made in code; the scene
/// reader checks the same rows with file locations.
template <class P>
void check_params(std::span<const Param<P>> table, const P& object) {
  const P defaults{};
  auto fail = [](const std::string& what, const std::string& wanted, const std::string& got) {
    throw std::invalid_argument(what + " must be " + wanted + " (got " + got + ")");
  };
  for (const Param<P>& row : table) {
    const std::string name = full_key(row.section, row.key);
    std::visit(
        [&](const auto& field) {
          using Field = std::decay_t<decltype(field)>;
          if constexpr (std::is_same_v<Field, double P::*> || std::is_same_v<Field, int P::*>) {
            const auto value = static_cast<double>(object.*field);
            const bool unset = !row.unset_name.empty() && object.*field == defaults.*field;
            if (!unset && !(std::isfinite(value) && row.range.contains(value))) {
              fail(name, row.range.describe(), number_text(value));
            }
          } else if constexpr (std::is_same_v<Field, glm::dvec3 P::*>) {
            for (int i = 0; i < 3; ++i) {
              const double value = (object.*field)[i];
              if (!(std::isfinite(value) && row.range.contains(value))) {
                fail(name + "[" + std::to_string(i) + "]", row.range.describe(),
                     number_text(value));
              }
            }
          } else if constexpr (std::is_same_v<Field, ChoiceField<P>>) {
            if (field.get(object, field.names) >= field.names.size()) {
              std::string names;
              for (const std::string_view n : field.names) {
                names += (names.empty() ? "\"" : ", \"") + std::string{n} + "\"";
              }
              throw std::invalid_argument(name + " must be one of " + names);
            }
          }
        },
        row.field);
  }
  // Order rules once every value is known to be in its range.
  for (const Param<P>& row : table) {
    if (row.order == Order::none) continue;
    const Param<P>& other = *find_param(table, row.section, row.other);
    const double a = number_value(row, object);
    const double b = number_value(other, object);
    const OrderWords words = order_words(row.order, a, b);
    if (!words.holds) {
      fail(full_key(row.section, row.key),
           std::string{words.wanted} + " " + full_key(other.section, other.key),
           number_text(a) + " " + std::string{words.got} + " " + number_text(b));
    }
  }
}

}  // namespace raintrace::sim
