// Helpers for povgen's tests that run the real POV-Ray (suites named PovRay*, ctest label
// `povray`): skip without it, run it in a folder, read its images back as floats
// (tests/support/pixels.h).
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "povgen/output_folder.h"
#include "povgen/templates.h"
#include "tests/support/command.h"
#include "tests/support/pixels.h"

namespace raintrace::povgen::testing {

/// A folder of the temporary directory for one test, unique to this process: engineers and CI
/// jobs sharing a machine (and /tmp) run the same tests at the same time.
inline std::filesystem::path scratch_folder(const std::string& name) {
  return ::raintrace::test_support::process_scratch_path("raintrace_" + name);
}

/// scratch_folder(name), emptied and made again: a test's own folder, with nothing left from an
/// earlier run.
inline std::filesystem::path empty_scratch_folder(const std::string& name) {
  const std::filesystem::path dir = scratch_folder(name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline bool have_povray() { return std::system("command -v povray >/dev/null 2>&1") == 0; }

#define SKIP_WITHOUT_POVRAY()                       \
  if (!::raintrace::povgen::testing::have_povray()) \
  GTEST_SKIP() << "povray is not installed: POV-Ray tests skipped"

/// Runs povray in `dir` with `args`; returns its exit status and leaves its output in povray.log.
inline int run_povray(const std::filesystem::path& dir, const std::string& args) {
  const std::string command =
      "cd '" + dir.string() + "' && povray " + args + " -D -V >povray.log 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// An empty scratch folder (scratch_folder(name)) holding the built-in `environment`'s template
/// as ENVIRONMENT.inc, for scenes that include it.
inline std::filesystem::path folder_with_environment(const std::string& name,
                                                     const std::string& environment) {
  const std::filesystem::path dir = empty_scratch_folder(name);
  write_file_atomic(dir / (environment + ".inc"), environment_template(environment));
  return dir;
}

/// The same with night_street's template.
inline std::filesystem::path folder_with_street(const std::string& name) {
  return folder_with_environment(name, "night_street");
}

inline std::string log_of(const std::filesystem::path& dir) {
  return read_file_bytes(dir / "povray.log").substr(0, 4000);
}

using raintrace::test_support::read_rgb;

/// POV-Ray's options for a square picture `pixels` wide: "+W<pixels> +H<pixels>".
inline std::string square_size(int pixels) {
  return "+W" + std::to_string(pixels) + " +H" + std::to_string(pixels);
}

/// Writes `scene` to dir/NAME.pov, traces it to dir/NAME.exr with `options` (size, antialiasing)
/// and reads the linear RGB back; a failed trace is a test failure (with POV-Ray's log) and gives
/// an empty image.
inline std::vector<float> trace_linear(const std::filesystem::path& dir, const std::string& name,
                                       const std::string& scene, const std::string& options) {
  write_file_atomic(dir / (name + ".pov"), scene);
  EXPECT_EQ(run_povray(dir, name + ".pov " + options + " +FE +O" + name + ".exr"), 0)
      << name << ":\n"
      << log_of(dir);
  return read_rgb(dir / (name + ".exr"));
}

/// How a light drawn two ways spreads, in the red of two pictures of it (`sharp`, `blurred`)
/// with `background` (the same scene without it) taken off: the blurred one's light and
/// brightest pixel as shares of the sharp one's, and how many pixels each lights past a
/// hundredth of the sharp one's brightest. `sharp_light` is 0 when the sharp picture shows
/// nothing.
struct LightSpread {
  double sharp_light = 0.0;
  double light_ratio = 0.0;
  double peak_ratio = 0.0;
  int sharp_lit = 0;
  int blurred_lit = 0;
};
inline LightSpread light_spread(const std::vector<float>& sharp, const std::vector<float>& blurred,
                                const std::vector<float>& background) {
  LightSpread spread;
  double blurred_light = 0.0, sharp_peak = 0.0, blurred_peak = 0.0;
  for (std::size_t i = 0; i < sharp.size(); i += 3) {
    spread.sharp_light += sharp[i] - background[i];
    blurred_light += blurred[i] - background[i];
    sharp_peak = std::max(sharp_peak, static_cast<double>(sharp[i] - background[i]));
    blurred_peak = std::max(blurred_peak, static_cast<double>(blurred[i] - background[i]));
  }
  if (spread.sharp_light <= 0.0) return spread;
  for (std::size_t i = 0; i < sharp.size(); i += 3) {
    if (sharp[i] - background[i] > 0.01 * sharp_peak) ++spread.sharp_lit;
    if (blurred[i] - background[i] > 0.01 * sharp_peak) ++spread.blurred_lit;
  }
  spread.light_ratio = blurred_light / spread.sharp_light;
  spread.peak_ratio = blurred_peak / sharp_peak;
  return spread;
}

/// A line of SDL that prints a value the scene computed to POV-Ray's debug stream, as
/// "value NAME v1 … vN": `expression` is a float (components 1) or a vector of `components`.
/// Read the values back with debug_values(); run POV-Ray without -GA, which silences #debug.
inline std::string debug_value_line(const std::string& name, const std::string& expression,
                                    int components = 1) {
  const std::string text =
      components == 1 ? "str(" + expression + ", 0, 6)"
                      : "vstr(" + std::to_string(components) + ", " + expression + ", \" \", 0, 6)";
  return "#debug concat(\"value " + name + " \", " + text + ", \"\\n\")\n";
}

/// Every value debug_value_line() printed into `log`, by name.
inline std::map<std::string, std::vector<double>> debug_values(const std::string& log) {
  std::map<std::string, std::vector<double>> values;
  const std::regex line(R"(value (\w+)((?: -?[0-9.]+)+))");
  for (auto it = std::sregex_iterator(log.begin(), log.end(), line); it != std::sregex_iterator();
       ++it) {
    std::vector<double>& numbers = values[(*it)[1]];
    numbers.clear();
    std::istringstream in{(*it)[2].str()};
    for (double number; in >> number;) numbers.push_back(number);
  }
  return values;
}

}  // namespace raintrace::povgen::testing
