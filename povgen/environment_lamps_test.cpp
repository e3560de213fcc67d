// The lamp table the rain uses against the template that draws the lamps.
#include "povgen/environment_lamps.h"

#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "povgen/templates.h"

namespace raintrace::povgen {
namespace {

double declared(const std::string& text, const std::string& name) {
  const std::regex pattern("#declare " + name + R"( = ([0-9.]+);)");
  std::smatch match;
  if (!std::regex_search(text, match, pattern)) {
    ADD_FAILURE() << name << " not declared";
    return 0.0;
  }
  return std::stod(match[1].str());
}

TEST(EnvironmentLamps, NightStreetsTableIsWhereTheTemplateDrawsItsLights) {
  const std::string& text = environment_template("night_street");
  const double kerb = declared(text, "RT_KerbX");
  const double height = declared(text, "RT_LampHeight");
  // The lens as RT_StreetLight places it.
  ASSERT_NE(text.find("#local Lens = <Side * (RT_KerbX - 1.4), RT_LampHeight - 0.07, Z>;"),
            std::string::npos);
  std::vector<glm::dvec3> drawn;
  const std::regex call(R"(\nRT_StreetLight\((-?[0-9.]+), (-?1), )");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), call); it != std::sregex_iterator();
       ++it) {
    const double z = std::stod((*it)[1].str());
    const double side = std::stod((*it)[2].str());
    drawn.emplace_back(side * (kerb - 1.4), height - 0.07, z);
  }
  const std::vector<glm::dvec3> table = environment_lamps("night_street");
  ASSERT_EQ(table.size(), drawn.size());
  ASSERT_GE(table.size(), 5u);
  for (std::size_t i = 0; i < table.size(); ++i) {
    EXPECT_NEAR(table[i].x, drawn[i].x, 1e-9) << i;
    EXPECT_NEAR(table[i].y, drawn[i].y, 1e-9) << i;
    EXPECT_NEAR(table[i].z, drawn[i].z, 1e-9) << i;
  }
}

// The shop signs keep clear of the lamp posts (RT_WordCentre) through a list of where the posts
// stand; a post moved in the RT_StreetLight calls and not in the list would stand across a
// word again.
std::vector<double> declared_array(const std::string& text, const std::string& name) {
  const std::regex pattern("#declare " + name + R"( = array\[[0-9]+\] \{([^}]*)\})");
  std::smatch match;
  if (!std::regex_search(text, match, pattern)) {
    ADD_FAILURE() << name << " not declared";
    return {};
  }
  std::vector<double> values;
  const std::string list = match[1].str();
  const std::regex number(R"(-?[0-9.]+)");
  for (auto it = std::sregex_iterator(list.begin(), list.end(), number);
       it != std::sregex_iterator(); ++it) {
    values.push_back(std::stod(it->str()));
  }
  return values;
}

TEST(EnvironmentLamps, NightStreetsPostListIsWhereTheTemplateDrawsItsPosts) {
  const std::string& text = environment_template("night_street");
  // The post's distance from the kerb, one value that RT_StreetLight stands it at and
  // RT_WordCentre expects it at.
  ASSERT_NE(text.find("#local PoleX = Side * (RT_KerbX + RT_PostOut);"), std::string::npos);
  ASSERT_NE(text.find("#local PostX = RT_Side * (RT_KerbX + RT_PostOut);"), std::string::npos);
  std::vector<double> drawn_z;
  std::vector<double> drawn_side;
  const std::regex call(R"(\nRT_StreetLight\((-?[0-9.]+), (-?1), )");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), call); it != std::sregex_iterator();
       ++it) {
    drawn_z.push_back(std::stod((*it)[1].str()));
    drawn_side.push_back(std::stod((*it)[2].str()));
  }
  ASSERT_GE(drawn_z.size(), 5u);
  EXPECT_EQ(declared_array(text, "RT_PostZ"), drawn_z);
  EXPECT_EQ(declared_array(text, "RT_PostSide"), drawn_side);
}

TEST(EnvironmentLamps, OtherEnvironmentsHaveNone) {
  EXPECT_TRUE(environment_lamps("field").empty());
  EXPECT_TRUE(environment_lamps("closeup").empty());
}

}  // namespace
}  // namespace raintrace::povgen
