// Tests for the typed, located reads on hand-built trees (no TOML involved).
#include "cli/scene_reader.h"

#include <gtest/gtest.h>
#include <functional>

#include "cli/scene.h"

namespace raintrace::cli {
namespace {

SceneNode number(double value, int line, int column) {
  SceneNode node;
  node.kind = SceneNode::Kind::floating;
  node.floating = value;
  node.where = {line, column};
  return node;
}

SceneNode table(std::vector<SceneEntry> entries) {
  SceneNode node;
  node.kind = SceneNode::Kind::table;
  node.where = {1, 1};
  node.entries = std::move(entries);
  return node;
}

std::string error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(EditDistance, CountsInsertionsDeletionsSubstitutionsAndTranspositions) {
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);  // the textbook example: k→s, e→i, +g
  EXPECT_EQ(edit_distance("rian", "rain"), 1u);       // one adjacent transposition
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("FPS", "fps"), 0u);  // case is folded
}

TEST(ClosestName, SuggestsOnlyLikelyTypos) {
  const std::vector<std::string> keys{"rate_mm_per_h", "near_m", "far_m"};
  EXPECT_EQ(closest_name("rate_mm_per_hr", keys), "rate_mm_per_h");
  EXPECT_EQ(closest_name("fa_m", keys), "far_m");
  EXPECT_EQ(closest_name("completely_different", keys), std::nullopt);
}

TEST(Range, DescribesItsBounds) {
  EXPECT_EQ(Range::closed(0, 500).describe(), "in [0, 500]");
  EXPECT_EQ(Range::open_closed(0, 240).describe(), "in (0, 240]");
  EXPECT_EQ(Range::at_least(0).describe(), ">= 0");
  EXPECT_EQ(Range::any().describe(), "finite");
  EXPECT_TRUE(Range::closed(0, 1).contains(0));
  EXPECT_FALSE(Range::open_closed(0, 1).contains(0));
  EXPECT_TRUE(Range::open_closed(0, 1).contains(1));
}

TEST(TableReader, LeavesTheTargetAloneWhenTheKeyIsAbsent) {
  const SceneNode root = table({});
  TableReader reader(root, "rain", "t.toml");
  double value = 42.0;
  EXPECT_FALSE(reader.read_number("rate_mm_per_h", value, Range::closed(0, 500)));
  EXPECT_EQ(value, 42.0);
  EXPECT_NO_THROW(reader.finish());
}

TEST(TableReader, ReportsRangeErrorsAtTheValue) {
  const SceneNode root = table({{"rate_mm_per_h", {4, 1}, number(-3, 4, 17)}});
  TableReader reader(root, "rain", "rain.toml");
  double value = 0.0;
  EXPECT_EQ(error_of([&] { reader.read_number("rate_mm_per_h", value, Range::closed(0, 500)); }),
            "rain.toml:4:17: rain.rate_mm_per_h: must be in [0, 500], got -3");
}

TEST(TableReader, FinishRejectsKeysNobodyReadAtTheKey) {
  const SceneNode root =
      table({{"near_m", {2, 1}, number(1, 2, 10)}, {"far_mm", {3, 1}, number(9, 3, 10)}});
  TableReader reader(root, "rain", "t.toml");
  double near = 0.0;
  double far = 0.0;
  reader.read_number("near_m", near, Range::any());
  reader.read_number("far_m", far, Range::any());
  EXPECT_EQ(near, 1.0);
  EXPECT_EQ(error_of([&] { reader.finish(); }),
            "t.toml:3:1: rain.far_mm: unknown key (did you mean 'far_m'?)");
}

TEST(TableReader, FinishListsKnownKeysWhenNothingIsClose) {
  const SceneNode root = table({{"zzzzzzzz", {2, 1}, number(1, 2, 12)}});
  TableReader reader(root, "splashes", "t.toml");
  double lifetime = 0.0;
  reader.read_number("lifetime_s", lifetime, Range::any());
  EXPECT_EQ(error_of([&] { reader.finish(); }),
            "t.toml:2:1: splashes.zzzzzzzz: unknown key (known keys of [splashes]: lifetime_s)");
}

}  // namespace
}  // namespace raintrace::cli
