// Number text: known answers, the rounding rules, round trips, rejection of non-finite values.
#include "povgen/number_format.h"

#include <gtest/gtest.h>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

namespace raintrace::povgen {
namespace {

TEST(NumberFormat, KnownAnswers) {
  EXPECT_EQ(format_number(1.5), "1.5");
  EXPECT_EQ(format_number(-0.25), "-0.25");
  EXPECT_EQ(format_number(0.0), "0");
  EXPECT_EQ(format_number(-0.0), "0");  // POV-Ray reads "-0" fine, but bytes must not vary
  EXPECT_EQ(format_number(100.0), "100");
  EXPECT_EQ(format_number(3.14159265358979), "3.141593");  // 7 significant digits
  EXPECT_EQ(format_number(1234567.8), "1234568");
  EXPECT_EQ(format_number(0.001), "0.001");
  EXPECT_EQ(format_number(0.00123456789), "0.001234568");
  EXPECT_EQ(format_number(9.9999999), "10");  // rounding carries into a new digit
  EXPECT_EQ(format_number(1e-5), "1e-05");
  EXPECT_EQ(format_number(2.5e9), "2.5e+09");
  EXPECT_EQ(format_number(1e-9 * 0.0), "0");
}

TEST(NumberFormat, AgreesWithToCharsSevenDigits) {
  // Away from exact ties, the text is std::to_chars(general, 7)'s (%.7g), in and out of the
  // fixed range.
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> exponent(-6.0, 10.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 200000; ++i) {
    const double v = (unit(rng) < 0.5 ? -1.0 : 1.0) * std::pow(10.0, exponent(rng));
    char expected[64];
    const auto r = std::to_chars(expected, expected + 64, v, std::chars_format::general, 7);
    ASSERT_EQ(format_number(v), std::string(expected, r.ptr)) << "value " << v;
  }
}

TEST(NumberFormat, RoundingCarriesIntoANewDigit) {
  // Just below a power of ten, rounding to 7 digits carries into a new digit.
  EXPECT_EQ(format_number(0.0099999996), "0.01");
  EXPECT_EQ(format_number(9.9999999), "10");
  EXPECT_EQ(format_number(999999.96), "1000000");
  // At the top of the fixed range the carry gives 8 digits where %.7g says "1e+07": the text
  // written since the first reference stills, kept.
  EXPECT_EQ(format_number(9999999.6), "10000000");
  EXPECT_EQ(format_number(0.00012345678), "0.0001234568");
}

TEST(NumberFormat, ExactTiesRoundAwayFromZero) {
  // 0.12890625 is exactly representable and halfway at the 7th digit: the atlas uv
  // coordinates are such values. std::to_chars would round to even ("0.1289062").
  EXPECT_EQ(format_number(0.12890625), "0.1289063");
  EXPECT_EQ(format_number(-0.12890625), "-0.1289063");
  EXPECT_EQ(format_number(1.5), "1.5");
}

TEST(NumberFormat, RoundTripsWithinHalfAUnitOfTheSeventhDigit) {
  // Seven significant digits: |parsed − v| ≤ 0.5·10^(e−6) with e = floor(log10|v|), so the
  // relative error is at most 5e-7.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> exponent(-12.0, 12.0);
  for (int i = 0; i < 100000; ++i) {
    const double v = std::pow(10.0, exponent(rng)) * (i % 2 ? 1.0 : -1.0);
    const std::string text = format_number(v);
    double parsed = 0.0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), parsed);
    ASSERT_EQ(r.ec, std::errc{}) << text;
    ASSERT_LE(std::fabs(parsed - v), 5.0000001e-7 * std::fabs(v)) << v << " -> " << text;
  }
}

std::string fixed5(double value) {
  std::string text;
  append_fixed5(text, value);
  return text;
}

/// What write_fixed5() promises: the shortest fixed-form text of the value rounded to 10 µm
/// (half away from zero, as llround), with "-0" as "0".
std::string shortest_fixed_of_rounded(double value) {
  const double rounded = static_cast<double>(std::llround(value * 1e5)) / 1e5;
  char text[64];
  const auto r =
      std::to_chars(text, text + 64, rounded == 0.0 ? 0.0 : rounded, std::chars_format::fixed);
  return {text, r.ptr};
}

TEST(NumberFormatFixed5, KnownAnswers) {
  EXPECT_EQ(fixed5(1.5), "1.5");
  EXPECT_EQ(fixed5(-0.25), "-0.25");
  EXPECT_EQ(fixed5(0.0), "0");
  EXPECT_EQ(fixed5(-0.0), "0");
  EXPECT_EQ(fixed5(-0.000004), "0");  // rounds to -0: still "0"
  EXPECT_EQ(fixed5(100.0), "100");
  EXPECT_EQ(fixed5(3.14159265358979), "3.14159");
  EXPECT_EQ(fixed5(-12.3456789), "-12.34568");
  EXPECT_EQ(fixed5(0.00001), "0.00001");
  EXPECT_EQ(fixed5(0.000015), "0.00002");  // half a step rounds away from zero
  EXPECT_EQ(fixed5(-0.000015), "-0.00002");
  EXPECT_EQ(fixed5(0.0000149), "0.00001");
  EXPECT_EQ(fixed5(999.999996), "1000");  // carries into a fourth integer digit
  EXPECT_EQ(fixed5(-1234.56789), "-1234.56789");
  EXPECT_EQ(fixed5(5e6), "5000000");
  EXPECT_EQ(fixed5(123456789.000001), "123456789");
  EXPECT_EQ(fixed5(2.5e12), "2.5e+12");  // beyond 10^12 m: write_number()
}

TEST(NumberFormatFixed5, IsTheShortestFixedTextOfTheRoundedValue) {
  // Magnitudes from 1 µm to 10^6 m, both signs, and float inputs as the streak corners are.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> exponent(-6.0, 6.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 300000; ++i) {
    double v = (unit(rng) < 0.5 ? -1.0 : 1.0) * std::pow(10.0, exponent(rng));
    if (i % 2) v = static_cast<float>(v);
    ASSERT_EQ(fixed5(v), shortest_fixed_of_rounded(v)) << "value " << v;
  }
}

TEST(NumberFormatFixed5, ExactStepsAndHalfStepsAtEveryDigitCount) {
  // k steps and k + 1/2 steps for k of 1..11 digits, each with 0..5 trailing zeros (so every
  // fraction length, and integers with no point at all).
  for (std::int64_t k = 1; k < 100'000'000'000; k = k * 10 + 3) {
    for (std::int64_t zeros = 1; zeros <= 100'000; zeros *= 10) {
      const auto steps = static_cast<double>(k * zeros);
      for (const double v : {steps * 1e-5, (steps + 0.5) * 1e-5}) {
        EXPECT_EQ(fixed5(v), shortest_fixed_of_rounded(v)) << "value " << v;
        EXPECT_EQ(fixed5(-v), shortest_fixed_of_rounded(-v)) << "value " << -v;
      }
    }
  }
}

TEST(NumberFormatFixed5, ParsesBackWithinHalfAStep) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coordinate(-200.0, 200.0);
  for (int i = 0; i < 100000; ++i) {
    const double v = coordinate(rng);
    const std::string text = fixed5(v);
    double parsed = 0.0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), parsed);
    ASSERT_EQ(r.ec, std::errc{}) << text;
    ASSERT_LE(std::fabs(parsed - v), 0.5e-5 + 1e-12) << v << " -> " << text;
  }
}

TEST(NumberFormatFixed5, RejectsNanAndInfinity) {
  EXPECT_THROW(fixed5(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
  EXPECT_THROW(fixed5(-std::numeric_limits<double>::infinity()), std::invalid_argument);
}

TEST(NumberFormat, RejectsNanAndInfinity) {
  EXPECT_THROW(format_number(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
  EXPECT_THROW(format_number(std::numeric_limits<double>::infinity()), std::invalid_argument);
  EXPECT_THROW(format_number(-std::numeric_limits<double>::infinity()), std::invalid_argument);
}

std::string index(std::uint64_t value) {
  std::string text;
  append_index(text, value);
  return text;
}

TEST(NumberFormat, WritesIndices) {
  EXPECT_EQ(index(0), "0");
  EXPECT_EQ(index(7), "7");
  EXPECT_EQ(index(10), "10");
  EXPECT_EQ(index(4000000), "4000000");
  EXPECT_EQ(index(12345678901ULL), "12345678901");
  EXPECT_EQ(index(18446744073709551615ULL), "18446744073709551615");
}

TEST(NumberFormat, AppendsToWhatIsThere) {
  std::string text = "<";
  append_number(text, 1.25);
  text += ',';
  append_fixed5(text, -0.5);
  text += ',';
  append_index(text, 42);
  EXPECT_EQ(text, "<1.25,-0.5,42");
}

}  // namespace
}  // namespace raintrace::povgen
