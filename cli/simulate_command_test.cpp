// End-to-end tests of the built `raintrace` program: `simulate` writes the statistics JSON with
// plausible physics, gives the same numbers whatever the thread count, and bad input ends with
// exit code 2 and one line on stderr that names file:line.
#include <sys/wait.h>

#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli/scene.h"
#include "sim/wind.h"

namespace {

namespace fs = std::filesystem;

const fs::path kSourceDir = RAINTRACE_SOURCE_DIR;
const fs::path kBinary = RAINTRACE_BINARY;

struct ProgramRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

fs::path scratch_dir() {
  // ctest runs tests in parallel processes: each test gets its own folder (and output files).
  const fs::path dir = fs::path(testing::TempDir()) /
                       ("raintrace_simulate_test_" +
                        std::string{testing::UnitTest::GetInstance()->current_test_info()->name()});
  fs::create_directories(dir);
  return dir;
}

/// Runs `raintrace ARGS` (ARGS already shell-quoted) and collects exit code, stdout, stderr.
ProgramRun raintrace(const std::string& args) {
  const fs::path dir = scratch_dir();
  const fs::path out = dir / "stdout.txt";
  const fs::path err = dir / "stderr.txt";
  const std::string command =
      "'" + kBinary.string() + "' " + args + " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int status = std::system(command.c_str());
  ProgramRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = read_text(out);
  run.err = read_text(err);
  return run;
}

std::string quote(const fs::path& path) { return "'" + path.string() + "'"; }

/// A small scene (drops only from 0.3 to 2 m: about 1 300 of them) so runs take a moment.
fs::path small_scene() {
  const fs::path path = scratch_dir() / "small.toml";
  std::ofstream(path) << "seed = 4\n[output]\nframes = 6\n[rain]\nfar_m = 2\n"
                         "[wind]\nvelocity_m_per_s = [1, 0, 0]\n";
  return path;
}

int count_lines(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

TEST(SimulateCommand, DefaultExampleWritesTheStatisticsJson) {
  const fs::path stats = scratch_dir() / "default_stats.json";
  fs::remove(stats);
  const ProgramRun run = raintrace("simulate " + quote(kSourceDir / "examples" / "default.toml") +
                                   " --frames 1-3 --stats " + quote(stats));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(count_lines(run.out), 1) << run.out;
  EXPECT_EQ(run.out.rfind("simulated frames 1-3 of ", 0), 0u) << run.out;

  const nlohmann::json json = nlohmann::json::parse(read_text(stats));
  EXPECT_EQ(json.at("frames").get<int>(), 3);
  // Frames are 1/24 s apart, rounded to whole 2 ms substeps.
  EXPECT_NEAR(json.at("dt_s").get<double>(), 1.0 / 24.0, 0.002);
  // default.toml promises 10k–60k drops in view: 5 mm/h Marshall-Palmer between 0.5 and 6 mm is
  // 634 drops/m³, the 60° 16:9 frustum from 0.3 to 6 m holds 54 m³, so about 34 000.
  const double count = json.at("drops").at("count").get<double>();
  EXPECT_GT(count, 10000.0);
  EXPECT_LT(count, 60000.0);
  const double mean_d = json.at("drops").at("mean_diameter_mm").get<double>();
  EXPECT_GT(mean_d, 0.5);
  EXPECT_LT(mean_d, 6.0);
  EXPECT_GT(json.at("drops").at("number_density_per_m3").get<double>(), 0.0);
  EXPECT_EQ(json.at("rain_rate_mm_per_h").at("configured").get<double>(), 5.0);
  // The water reaching the ground is the configured rate, give or take the noise of 0.08 s.
  EXPECT_NEAR(json.at("rain_rate_mm_per_h").at("measured_at_ground").get<double>(), 5.0, 1.25);

  // Fall speeds follow Atlas et al. (1973)'s fit to Gunn & Kinzer (1949),
  // v = 9.65 − 10.3·e^(−0.6·D) m/s (D in mm), at each 0.1 mm bin's mean diameter: within 3 %
  // (the simulation's own drag law is within 2 % of Gunn & Kinzer; a bin's curvature adds
  // < 2 mm/s), and grow with diameter. Each bin's edges are 0.1 mm apart and hold its mean.
  const auto& bins = json.at("fall_speed_by_diameter");
  ASSERT_GE(bins.size(), 10u);
  double previous_speed = 0.0;
  for (const auto& bin : bins) {
    const double lo = bin.at("diameter_min_mm").get<double>();
    const double hi = bin.at("diameter_max_mm").get<double>();
    const double d = bin.at("mean_diameter_mm").get<double>();
    const double v = bin.at("speed_m_per_s").get<double>();
    EXPECT_NEAR(hi - lo, 0.1, 1e-9);
    EXPECT_GE(d, lo);
    EXPECT_LT(d, hi);
    EXPECT_GE(bin.at("speed_sd_m_per_s").get<double>(), 0.0);
    if (bin.at("samples").get<std::uint64_t>() < 1000) continue;
    const double expected = 9.65 - 10.3 * std::exp(-0.6 * d);
    EXPECT_NEAR(v, expected, 0.03 * expected) << "diameter " << d << " mm";
    EXPECT_GT(v, previous_speed) << "diameter " << d << " mm";
    previous_speed = v;
  }
  // One entry per frame, 1/24 s apart.
  const auto& motion = json.at("horizontal_motion_by_frame");
  ASSERT_EQ(motion.size(), 3u);
  EXPECT_NEAR(motion.at(1).at("time_s").get<double>() - motion.at(0).at("time_s").get<double>(),
              1.0 / 24.0, 0.002);
  // The wind reported is the one at look_at: the steady 0.8 m/s breeze plus the eddies there
  // (default.toml's turbulence_m_per_s), as the scene's own wind field gives it.
  const raintrace::cli::Scene scene =
      raintrace::cli::load_scene_file(kSourceDir / "examples" / "default.toml");
  ASSERT_GT(scene.sim.wind.turbulence_m_per_s, 0.0);
  const raintrace::sim::Wind wind(scene.sim.wind, scene.sim.seed);
  for (const auto& frame : motion) {
    const glm::vec3 at_look =
        wind.at(glm::vec3(scene.sim.camera.look_at), frame.at("time_s").get<double>());
    EXPECT_NEAR(frame.at("wind_m_per_s").at(0).get<double>(), at_look.x, 1e-5);
    EXPECT_NEAR(frame.at("wind_m_per_s").at(1).get<double>(), at_look.z, 1e-5);
  }
  // A 0.8 m/s breeze along +x carries the drops with it; the eddies (0.8 m/s RMS, 4 m across)
  // average out over the thousands of drops in view, so the mean drift stays near the breeze's
  // and across the street near zero.
  const auto& drift = json.at("horizontal_velocity_m_per_s");
  EXPECT_GT(drift.at(0).get<double>(), 0.4);
  EXPECT_LT(drift.at(0).get<double>(), 1.0);
  EXPECT_NEAR(drift.at(1).get<double>(), 0.0, 0.15);
  EXPECT_GT(json.at("splashes").get<std::uint64_t>(), 0u);
  // The ground: drops reach it at the rain's number flux ∫N(D)·v(D) dD, 1 816 per m² and
  // second at 5 mm/h (Marshall-Palmer from 0.5 to 6 mm, scaled to the rate: DropSizeModel),
  // to within the noise of the far, thinned impacts over 0.08 s (10 %); most of them do not
  // splash (65 % are under 1 mm), and a quarter land in night_street's puddles (the default
  // coverage there) and ripple.
  constexpr double kFlux5 = 1816.4;
  const auto& ground = json.at("ground");
  EXPECT_EQ(ground.at("splashes").get<std::uint64_t>(), json.at("splashes").get<std::uint64_t>());
  const double impacts = ground.at("impacts").get<double>();
  EXPECT_GT(impacts, 0.0);
  EXPECT_LT(ground.at("splashes").get<double>(), 0.5 * impacts);
  EXPECT_GT(ground.at("ripples").get<double>(), 0.1 * impacts);
  EXPECT_LT(ground.at("ripples").get<double>(), 0.45 * impacts);
  EXPECT_LT(ground.at("impacts_simulated").get<double>(), impacts);
  EXPECT_GT(ground.at("area_m2").get<double>(), 100.0);
  EXPECT_NEAR(ground.at("impacts_per_m2_s").get<double>(), kFlux5, 0.1 * kFlux5);
  EXPECT_EQ(json.at("lightning").at("strikes").get<std::uint64_t>(), 0u);
  EXPECT_EQ(json.at("lightning").at("segments").get<std::uint64_t>(), 0u);
}

TEST(SimulateCommand, SameSeedGivesIdenticalStatisticsWhateverTheThreadCount) {
  const std::string scene = quote(small_scene());
  const ProgramRun one = raintrace("simulate " + scene + " --threads 1 --stats -");
  const ProgramRun two = raintrace("simulate " + scene + " --threads 2 --stats -");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  ASSERT_EQ(two.exit_code, 0) << two.err;
  EXPECT_EQ(one.out, two.out);
  // With the JSON on stdout the summary moves to stderr.
  EXPECT_NE(one.err.find("simulated frames 1-6"), std::string::npos) << one.err;
  EXPECT_EQ(nlohmann::json::parse(one.out).at("seed").get<std::uint64_t>(), 4u);

  const ProgramRun other = raintrace("simulate " + scene + " --seed 5 --stats -");
  ASSERT_EQ(other.exit_code, 0) << other.err;
  EXPECT_EQ(nlohmann::json::parse(other.out).at("seed").get<std::uint64_t>(), 5u);
  EXPECT_NE(nlohmann::json::parse(other.out).at("drops"),
            nlohmann::json::parse(one.out).at("drops"));
}

TEST(SimulateCommand, BadSceneGivesExitCode2AndOneLineNamingFileAndLine) {
  const fs::path bad = scratch_dir() / "bad.toml";
  std::ofstream(bad) << "seed = 1\n[rain]\nrate_mm_per_h = -3\n";
  const ProgramRun run = raintrace("simulate " + quote(bad));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(run.err, "raintrace: error: " + bad.string() +
                         ":3:17: rain.rate_mm_per_h: must be in [0, 500], got -3\n");
}

TEST(SimulateCommand, BadOptionsGiveExitCode2) {
  const std::string scene = quote(small_scene());
  for (const std::string options : {"--frames 0-3", "--frames 7", "--seed -1", "--seed x",
                                    "--threads -2", "--no-such-option"}) {
    const ProgramRun run = raintrace("simulate " + scene + " " + options);
    EXPECT_EQ(run.exit_code, 2) << options << ": " << run.err;
    EXPECT_FALSE(run.err.empty()) << options;
  }
  EXPECT_EQ(raintrace("simulate " + quote(scratch_dir() / "missing.toml")).exit_code, 2);
}

TEST(MainHelp, ListsEveryCommandWithADescriptionAndAnExample) {
  const ProgramRun run = raintrace("--help");
  EXPECT_EQ(run.exit_code, 0);
  for (const std::string command : {"simulate", "export", "render", "compare"}) {
    EXPECT_NE(run.out.find("\n  " + command + " "), std::string::npos) << command;
    EXPECT_NE(run.out.find("raintrace " + command + " "), std::string::npos) << command;
  }
  const ProgramRun simulate_help = raintrace("simulate --help");
  EXPECT_EQ(simulate_help.exit_code, 0);
  for (const std::string option : {"--frames", "--seed", "--stats", "--threads"}) {
    EXPECT_NE(simulate_help.out.find("raintrace simulate examples/default.toml " + option),
              std::string::npos)
        << option << " has no example";
  }
}

}  // namespace
