// Parameter tables: ranges, number words, and check_params/validate against every row.
#include "sim/param_table.h"

#include <gtest/gtest.h>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "sim/params.h"

namespace raintrace::sim {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(Range, ContainsItsClosedEndsAndNotItsOpenOnes) {
  EXPECT_TRUE(Range::closed(0, 1).contains(0));
  EXPECT_TRUE(Range::closed(0, 1).contains(1));
  EXPECT_FALSE(Range::open_closed(0, 1).contains(0));
  EXPECT_TRUE(Range::open_closed(0, 1).contains(1));
  EXPECT_FALSE(Range::open(0, 1).contains(1));
  EXPECT_TRUE(Range::at_most(1e6).contains(-1));
  EXPECT_FALSE(Range::any().contains(std::nan("")));
  EXPECT_FALSE(Range::closed(0, 1).contains(std::nan("")));
}

TEST(Range, DescribesItsBoundsAsTheMessagesSayThem) {
  EXPECT_EQ(Range::closed(0, 500).describe(), "in [0, 500]");
  EXPECT_EQ(Range::open_closed(0, 240).describe(), "in (0, 240]");
  EXPECT_EQ(Range::open(1, 170).describe(), "in (1, 170)");
  EXPECT_EQ(Range::closed(-1e5, 1e5).describe(), "in [-100000, 100000]");
  EXPECT_EQ(Range::closed(1e-4, 0.02).describe(), "in [0.0001, 0.02]");
  EXPECT_EQ(Range::at_least(0).describe(), ">= 0");
  EXPECT_EQ(Range::at_most(1e6).describe(), "<= 1000000");
  EXPECT_EQ(Range::any().describe(), "finite");
}

TEST(NumberText, ShortestRoundTripInFixedFormBetween1eMinus4And1e16) {
  EXPECT_EQ(number_text(0.0), "0");
  EXPECT_EQ(number_text(-3.0), "-3");
  EXPECT_EQ(number_text(0.1), "0.1");
  EXPECT_EQ(number_text(1.0 / 3.0), "0.3333333333333333");
  EXPECT_EQ(number_text(0.0001), "0.0001");
  EXPECT_EQ(number_text(0.00001), "1e-05");
  EXPECT_EQ(number_text(1e15), "1000000000000000");
  EXPECT_EQ(number_text(1e16), "1e+16");
  EXPECT_EQ(number_text(kInf), "inf");
  EXPECT_EQ(number_text(-kInf), "-inf");
}

std::string error_of(const SimParams& p) {
  try {
    validate(p);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(Validate, DefaultsAreValid) { EXPECT_EQ(error_of(SimParams{}), ""); }

/// The field of a number row.
template <class P>
double& number_field(const Param<P>& row, P& object) {
  return object.*std::get<double P::*>(row.field);
}

TEST(Validate, EveryNumberRowAcceptsItsBoundsAndRejectsJustBeyond) {
  // For each number row of the simulation's tables: the next double beyond either end is
  // rejected with the key's full name and range; a closed end is not out of range (it may
  // still break an order rule with the partner's default, as diameter_max_mm = 0.1 does).
  auto probe = [](auto table, auto member_of) {
    for (const auto& row : table) {
      if (row.type != ParamType::number) continue;
      const std::string name = full_key(row.section, row.key);
      for (const bool at_max : {false, true}) {
        const double end = at_max ? row.range.max : row.range.min;
        if (!std::isfinite(end)) continue;
        const bool open = at_max ? row.range.max_open : row.range.min_open;
        const double beyond = std::nextafter(end, at_max ? kInf : -kInf);
        SimParams p;
        auto& object = member_of(p);
        number_field(row, object) = beyond;
        const std::string error = error_of(p);
        EXPECT_EQ(error.rfind(name + " must be " + row.range.describe(), 0), 0u)
            << name << " = " << beyond << ": " << error;
        if (open) continue;
        number_field(row, object) = end;
        const std::string inside = error_of(p);
        EXPECT_EQ(inside.find(name + " must be in"), std::string::npos) << inside;
      }
    }
  };
  probe(std::span<const Param<RainParams>>(kRainParams),
        [](SimParams& p) -> RainParams& { return p.rain; });
  probe(std::span<const Param<WindParams>>(kWindParams),
        [](SimParams& p) -> WindParams& { return p.wind; });
  probe(std::span<const Param<SplashParams>>(kSplashParams),
        [](SimParams& p) -> SplashParams& { return p.splashes; });
  probe(std::span<const Param<LightningParams>>(kLightningParams),
        [](SimParams& p) -> LightningParams& { return p.lightning; });
  probe(std::span<const Param<Camera>>(kCameraParams),
        [](SimParams& p) -> Camera& { return p.camera; });
  probe(std::span<const Param<SimParams>>(kSimParams),
        [](SimParams& p) -> SimParams& { return p; });
}

TEST(Validate, RangesThatDisagreedBeforeTheTablesAreNowOne) {
  // lightning.distance_min_m was [0, 1e5] here and [0, 10000] in the reader; fov (0, 180) in
  // povgen and (1, 170) in the reader; near_m "positive" here and (0, 1000) in the reader.
  SimParams p;
  p.lightning.distance_min_m = 20000;
  p.lightning.distance_max_m = 20000;
  EXPECT_EQ(error_of(p), "lightning.distance_min_m must be in [0, 10000] (got 20000)");
  p = SimParams{};
  p.camera.fov_deg = 0.5;
  EXPECT_EQ(error_of(p), "camera.fov_deg must be in (1, 170) (got 0.5)");
  p = SimParams{};
  p.rain.near_m = 1000;
  p.rain.far_m = 1000;
  EXPECT_EQ(error_of(p), "rain.near_m must be in (0, 1000) (got 1000)");
}

TEST(Validate, OrderRulesNameBothKeys) {
  SimParams p;
  p.rain.far_m = 0.2;
  EXPECT_EQ(error_of(p), "rain.far_m must be > rain.near_m (got 0.2 <= 0.3)");
  p = SimParams{};
  p.rain.diameter_min_mm = 7;
  EXPECT_EQ(error_of(p), "rain.diameter_min_mm must be <= rain.diameter_max_mm (got 7 > 6)");
}

TEST(Validate, IntegersVectorsAndNonFiniteValues) {
  SimParams p;
  p.splashes.droplets = 65;
  EXPECT_EQ(error_of(p), "splashes.droplets must be in [0, 64] (got 65)");
  p = SimParams{};
  p.wind.velocity_m_per_s.z = -61;
  EXPECT_EQ(error_of(p), "wind.velocity_m_per_s[2] must be in [-60, 60] (got -61)");
  p = SimParams{};
  p.lightning.first_strike_s = -kInf;  // the range has no lower end, but it must be finite
  EXPECT_EQ(error_of(p), "lightning.first_strike_s must be <= 1000000 (got -inf)");
  p = SimParams{};
  p.rain.colour.g = std::nan("");
  EXPECT_EQ(error_of(p).rfind("rain.colour[1] must be in [0, 1]", 0), 0u) << error_of(p);
}

TEST(Validate, AnUnsetDefaultIsSkippedButOtherValuesAreChecked) {
  SimParams p;
  ASSERT_EQ(p.prewarm_s, -1.0);  // "automatic"
  EXPECT_EQ(error_of(p), "");
  p.prewarm_s = -2.0;
  EXPECT_EQ(error_of(p), "simulation.prewarm_s must be in [0, 60] (got -2)");
}

TEST(Validate, ChoicesMustNameAValue) {
  SimParams p;
  p.rain.distribution = static_cast<DropSizeDistribution>(7);
  EXPECT_EQ(error_of(p), "rain.distribution must be one of \"marshall-palmer\", \"uniform\"");
}

TEST(Validate, CameraAndGustRulesThatAreNotRanges) {
  SimParams p;
  p.camera.look_at = p.camera.position;
  EXPECT_EQ(error_of(p), "camera.look_at must differ from camera.position");
  p = SimParams{};
  p.camera.look_at = p.camera.position + glm::dvec3{0, 3, 0};
  EXPECT_EQ(error_of(p), "camera.look_at must not lie straight above or below camera.position");
  p = SimParams{};
  p.camera.aspect = 0;
  EXPECT_EQ(error_of(p), "camera.aspect must be > 0 (got 0)");
  p = SimParams{};
  p.wind.gust_direction = {0, 1, 0};
  EXPECT_EQ(error_of(p), "wind.gust_direction must point somewhere horizontally");
}

// A table whose order rule names a key it does not have is refused at compile time.
struct Pair {
  double low = 0;
  double high = 1;
};
constexpr Param<Pair> kGoodPair[] = {
    number("pair", "low", &Pair::low, "m", Range::any()).at_most("high"),
    number("pair", "high", &Pair::high, "m", Range::any()),
};
constexpr Param<Pair> kBadPair[] = {
    number("pair", "low", &Pair::low, "m", Range::any()).at_most("hihg"),
    number("pair", "high", &Pair::high, "m", Range::any()),
};
constexpr Param<Pair> kTwiceTheSameKey[] = {
    number("pair", "low", &Pair::low, "m", Range::any()),
    number("pair", "low", &Pair::high, "m", Range::any()),
};
static_assert(well_formed<Pair>(kGoodPair));
static_assert(!well_formed<Pair>(kBadPair));
static_assert(!well_formed<Pair>(kTwiceTheSameKey));

TEST(ParamTable, FindsRowsBySectionAndKey) {
  const Param<RainParams>* row = find_param<RainParams>(kRainParams, "rain", "rate_mm_per_h");
  ASSERT_NE(row, nullptr);
  EXPECT_EQ(row->unit, "mm/h");
  EXPECT_EQ(find_param<RainParams>(kRainParams, "wind", "rate_mm_per_h"), nullptr);
}

}  // namespace
}  // namespace raintrace::sim
