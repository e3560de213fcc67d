// The parameter tables as the reader uses them: the reader and the tables' own checks
// (sim::check_params, behind sim::validate and povgen::validate) accept and refuse the same
// values, and docs/scene-format.md's generated columns match the tables.
#include "cli/scene_tables.h"

#include <fmt/core.h>
#include <gtest/gtest.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "cli/scene.h"
#include "cli/scene_format_doc.h"
#include "tests/support/command.h"

namespace raintrace::cli {
namespace {

namespace fs = std::filesystem;
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(NumberText, WordsNumbersAsFmtDoes) {
  // The reader words values with fmt's "{}" and ranges with sim::number_text: they must agree.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> exponent(-30.0, 30.0);
  for (int i = 0; i < 100000; ++i) {
    const double v = (i % 2 ? -1.0 : 1.0) * std::pow(10.0, exponent(rng));
    ASSERT_EQ(sim::number_text(v), fmt::format("{}", v)) << v;
  }
  for (const double v : {0.0, 1.0, 100000.0, 1e15, 1e16, 0.0001, 0.00001, 123456789.0}) {
    EXPECT_EQ(sim::number_text(v), fmt::format("{}", v)) << v;
  }
}

/// Whether the tables' own checks accept every field of `scene` (ranges, choices and order
/// rules of every table, as sim::validate and povgen::validate run them).
bool tables_accept(const Scene& scene) {
  bool ok = true;
  for_each_table(scene, [&](auto table, const auto& object) {
    using P = std::remove_cvref_t<decltype(object)>;
    try {
      sim::check_params<P>(table, object);
    } catch (const std::invalid_argument&) {
      ok = false;
    }
  });
  return ok;
}

/// One key set to one value: as a scene file, and as the field of a Scene.
struct Probe {
  std::string section;
  std::string key;
  double value = 0;  ///< for a vector, its x (y and z keep their defaults)
  std::string toml;
};

/// `scene` with the probe's field set directly, as code would set it.
Scene with_field_set(const Probe& probe) {
  Scene scene;
  for_each_table(scene, [&](auto table, auto& object) {
    using P = std::remove_cvref_t<decltype(object)>;
    const sim::Param<P>* row = sim::find_param(table, probe.section, probe.key);
    if (row == nullptr) return;
    if (const auto* field = std::get_if<double P::*>(&row->field)) object.*(*field) = probe.value;
    if (const auto* field = std::get_if<int P::*>(&row->field)) {
      object.*(*field) = static_cast<int>(probe.value);
    }
    if (const auto* field = std::get_if<glm::dvec3 P::*>(&row->field)) {
      (object.*(*field)).x = probe.value;
    }
  });
  return scene;
}

/// For every number, integer and vector row: each finite end of its range and the next value
/// beyond it.
std::vector<Probe> probes() {
  std::vector<Probe> out;
  const Scene defaults;
  for_each_table(defaults, [&](auto table, const auto& object) {
    using P = std::remove_cvref_t<decltype(object)>;
    for (const sim::Param<P>& row : table) {
      const bool is_int = std::holds_alternative<int P::*>(row.field);
      const auto* vector = std::get_if<glm::dvec3 P::*>(&row.field);
      if (!is_int && vector == nullptr && !std::holds_alternative<double P::*>(row.field)) {
        continue;
      }
      for (const double end : {row.range.min, row.range.max}) {
        if (!std::isfinite(end)) continue;
        const double outward = end == row.range.min ? -kInf : kInf;
        const double beyond = is_int ? end + (outward > 0 ? 1 : -1) : std::nextafter(end, outward);
        for (const double value : {end, beyond}) {
          Probe probe{std::string{row.section}, std::string{row.key}, value, ""};
          std::string text = fmt::format("{}", value);
          if (vector != nullptr) {
            const glm::dvec3& v = object.*(*vector);
            text = fmt::format("[{}, {}, {}]", value, v.y, v.z);
          }
          if (!row.section.empty()) probe.toml = fmt::format("[{}]\n", row.section);
          // Blades and the barrel's rim need an opening (rules between two keys, which the
          // tables do not hold).
          if (row.key == "aperture_blades" || row.key == "optical_vignetting") {
            probe.toml += "aperture_m = 0.008\n";
          }
          probe.toml += probe.key + " = " + text + "\n";
          out.push_back(probe);
        }
      }
    }
  });
  return out;
}

TEST(SceneTables, ReaderAndTableChecksAcceptTheSameValues) {
  const std::vector<Probe> all = probes();
  ASSERT_GT(all.size(), 150u);
  int accepted = 0;
  for (const Probe& probe : all) {
    bool loaded = true;
    std::string error;
    try {
      load_scene_string(probe.toml, "t.toml", ".");
    } catch (const SceneError& e) {
      loaded = false;
      error = e.what();
    }
    EXPECT_EQ(loaded, tables_accept(with_field_set(probe))) << probe.toml << error;
    accepted += loaded;
  }
  EXPECT_GT(accepted, 50);
}

TEST(SceneTables, EveryExampleSceneAlsoPassesTheTableChecks) {
  for (const auto& entry : fs::directory_iterator(fs::path(RAINTRACE_SOURCE_DIR) / "examples")) {
    if (entry.path().extension() != ".toml") continue;
    const Scene scene = load_scene_file(entry.path());
    EXPECT_TRUE(tables_accept(scene)) << entry.path();
  }
}

TEST(SceneTables, EveryKeyIsReadOnceInItsSection) {
  // A key that two tables claim for one section would be read twice and documented twice.
  std::vector<std::string> keys;
  for (const SceneFormatRow& row : scene_format_rows()) {
    const std::string key = row.section + "." + row.key;
    EXPECT_EQ(std::count(keys.begin(), keys.end(), key), 0) << key;
    keys.push_back(key);
    EXPECT_NE(std::find(std::begin(kSections), std::end(kSections), row.section),
              std::end(kSections))
        << key << ": its section is not in kSections, so the reader never reads it";
  }
}

using test_support::read_text;

TEST(SceneFormatDoc, ColumnsMatchTheParameterTables) {
  const fs::path doc = fs::path(RAINTRACE_SOURCE_DIR) / "docs" / "scene-format.md";
  const std::string text = read_text(doc);
  ASSERT_FALSE(text.empty()) << doc;
  const std::string generated = update_scene_format_doc(text);
  if (generated == text) return;
  // Name the first line that differs, then fail.
  std::istringstream a(text), b(generated);
  std::string line_a, line_b;
  int line = 0;
  while (std::getline(a, line_a) && std::getline(b, line_b) && line_a == line_b) ++line;
  ADD_FAILURE() << "docs/scene-format.md line " << line + 1 << " differs from the parameter "
                << "tables; run `cmake --build build --target update-scene-format` and review.\n"
                << "  doc:       " << line_a << "\n  generated: " << line_b;
}

TEST(SceneFormatDoc, AddsMissingKeysAndRefusesKeysNoTableHas) {
  const std::string doc = read_text(fs::path(RAINTRACE_SOURCE_DIR) / "docs" / "scene-format.md");
  const std::string droplets = "| `droplets` | integer | — | 32 | [0, 64] |";
  const std::size_t row = doc.find(droplets);
  ASSERT_NE(row, std::string::npos);
  // A key the doc lacks comes back at the end of its section's table, to be described.
  std::string without = doc;
  without.erase(row, doc.find('\n', row) + 1 - row);
  const std::string updated = update_scene_format_doc(without);
  EXPECT_NE(updated.find("throw crown-splash droplets |\n| `lifetime_s` | number | s | 0.3 | "
                         "(0, 2] | longest a droplet flies before it is dropped (it fades over the "
                         "last third); most land much sooner |\n" +
                         droplets + " TODO |\n\nWhich drops splash"),
            std::string::npos)
      << updated.substr(updated.find("## `[splashes]`"), 600);
  // A documented key that no table has is an error, not a row silently kept.
  std::string extra = doc;
  extra.insert(row, "| `puddles` | boolean | — | true | | puddles on the ground |\n");
  EXPECT_THROW(update_scene_format_doc(extra), std::runtime_error);
  // So is a section with keys but no table.
  std::string no_table = doc;
  no_table.replace(no_table.find("## `[splashes]`"), 15, "## Splashes");
  EXPECT_THROW(update_scene_format_doc(no_table), std::runtime_error);
}

}  // namespace
}  // namespace raintrace::cli
