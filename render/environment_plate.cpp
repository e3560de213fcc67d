// The plate's life cycle. One rule keeps frames honest: kPlateImage exists only while it is
// complete, so a frame sees either the finished plate or none (and traces the full environment).
// The sidecar is removed before the image and written after it, so a killed run at worst leaves
// a plate without a current sidecar, which the next run redoes.
#include "render/environment_plate.h"

#include <fmt/core.h>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "output/disk_space.h"
#include "output/image_check.h"
#include "povgen/content_hash.h"
#include "povgen/ground_scene.h"
#include "povgen/output_folder.h"
#include "render/povray_command.h"
#include "render/process.h"
#include "render/text_file.h"

namespace raintrace::render {
namespace {

using output::image_is_complete;

bool plate_is_current(const std::filesystem::path& out, int width, int height,
                      const std::string& inputs_hash) {
  std::error_code ec;
  if (!std::filesystem::exists(out / kPlateSidecar, ec)) return false;
  return read_text(out / kPlateSidecar) == inputs_hash + "\n" &&
         image_is_complete(out / kPlateImage, width, height);
}

}  // namespace

std::string environment_plate_inputs_hash(const std::filesystem::path& out_dir) {
  povgen::ContentHasher hasher;
  // Everything plate.pov reads: the puddles too (the wet ground's include and its mask).
  for (const char* name :
       {povgen::kPlateIni, povgen::kPlatePov, povgen::kSceneInclude, povgen::kEnvironmentInclude,
        povgen::kMaterialsInclude, povgen::kGroundInclude, povgen::kPuddleMask}) {
    // Name and length frame each file's bytes, so moving text between files changes the hash.
    hasher.update(name);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(out_dir / name, ec)) {
      hasher.update("\nmissing\n");
      continue;
    }
    const std::string bytes = read_text(out_dir / name);
    hasher.update(fmt::format("\n{}\n", bytes.size()));
    hasher.update(bytes);
  }
  return hasher.hex();
}

EnvironmentPlate::EnvironmentPlate(std::filesystem::path out_dir, int width, int height,
                                   const std::atomic<bool>* stop)
    : m_out{std::move(out_dir)}, m_width{width}, m_height{height}, m_stop{stop} {
  if (!std::filesystem::exists(m_out / povgen::kPlateIni)) {
    m_done = true;
    return;
  }
  // Hashed before POV-Ray reads the inputs: if they change meanwhile, the sidecar names the
  // older inputs and the next run renders again (never the other way round).
  m_inputs_hash = environment_plate_inputs_hash(m_out);
  if (plate_is_current(m_out, m_width, m_height, m_inputs_hash)) {
    m_done = true;
    return;
  }
  // A stale plate must not be seen by any frame from now on, and its sidecar goes first.
  std::filesystem::remove(m_out / kPlateSidecar);
  std::filesystem::remove(m_out / kPlateImage);
  std::filesystem::create_directories(m_out / "logs");
  std::filesystem::create_directories(m_out / temp_dir_name());
  prepare_povray_home(m_out);
  start_povray();
}

void EnvironmentPlate::start_povray() {
  std::filesystem::remove(m_out / environment_plate_temp_name());
  ProcessSpec spec;
  spec.argv = environment_plate_argv();
  spec.working_dir = m_out;
  spec.env = povray_env(m_out);
  spec.log_path = m_out / kPlateLog;
  m_process = std::make_unique<ChildProcess>(spec);
  ++m_starts;
}

// ChildProcess's own destructor stops a POV-Ray still running.
EnvironmentPlate::~EnvironmentPlate() = default;

bool EnvironmentPlate::poll() {
  if (m_done) return true;
  if (m_stop != nullptr && m_stop->load()) {
    m_process->stop();
    std::filesystem::remove(m_out / environment_plate_temp_name());
    m_interrupted = true;
    m_problem = "interrupted";
    m_done = true;
    return true;
  }
  if (const auto code = m_process->poll()) finish(*code);
  return m_done;
}

void EnvironmentPlate::wait(const std::function<void()>& on_tick) {
  while (!poll()) {
    if (on_tick) on_tick();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

void EnvironmentPlate::finish(int exit_code) {
  const std::string log_text = exit_code != 0 ? read_text(m_out / kPlateLog) : std::string{};
  // POV-Ray gave up before reading plate.ini (a loaded machine): start it again, as the frames'
  // runner does, since without a plate every frame traces the whole environment.
  const bool did_not_start = povray_did_not_start(log_text);
  if (did_not_start && m_starts < kPovrayStartAttempts) {
    start_povray();
    return;
  }
  m_done = true;
  const auto temp = m_out / environment_plate_temp_name();
  if (exit_code != 0) {
    // A full disk is not a plate problem the frames can work around: they would fail too.
    output::throw_if_out_of_space(
        m_out, static_cast<std::uint64_t>(m_width) * m_height * 8 + 65536,
        fmt::format("POV-Ray could not write the environment plate into {} (log {})",
                    m_out.string(), kPlateLog));
    auto lines = povray_error_lines(log_text);
    if (did_not_start) {
      lines.push_back(povray_did_not_start_line(m_starts));
    }
    std::string reason;
    for (const auto& line : lines) reason += (reason.empty() ? "" : " | ") + line;
    fail(fmt::format("povray plate.ini exited with code {}{}{}", exit_code,
                     reason.empty() ? "" : ": ", reason));
    return;
  }
  std::string why;
  if (!image_is_complete(temp, m_width, m_height, &why)) {
    fail(fmt::format("{}: {}", environment_plate_temp_name(), why));
    return;
  }
  std::filesystem::create_directories((m_out / kPlateImage).parent_path());
  std::filesystem::rename(temp, m_out / kPlateImage);
  povgen::write_file_atomic(m_out / kPlateSidecar, m_inputs_hash + "\n");
}

void EnvironmentPlate::fail(std::string reason) {
  // Frames then trace the full environment: correct, only slower.
  std::filesystem::remove(m_out / environment_plate_temp_name());
  std::filesystem::remove(m_out / kPlateImage);
  m_problem = fmt::format("{}; log {}", reason, kPlateLog);
}

std::string environment_plate_notice(const EnvironmentPlate& plate) {
  return fmt::format("environment plate failed ({}): frames render the full environment",
                     plate.problem());
}

}  // namespace raintrace::render
