// The environment plate of a preview folder: plate.ini renders the scene's environment once,
// without rain, into textures/environment_plate.exr, and each frame's scene.inc draws that image
// behind the rain when it exists at the frame size, instead of tracing the environment again.
// Frames look for the file when POV-Ray parses them, so the plate must be in place (or known to
// have failed, and absent) before any frame's POV-Ray starts, or images would depend on timing.
#pragma once

#include <atomic>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "povgen/scene_files.h"

namespace raintrace::render {

class ChildProcess;

/// The plate image and the hash of the inputs it was made from, relative to the output folder.
/// The sidecar is written only after the image is in place, so a plate without a matching
/// sidecar is never trusted.
inline constexpr const char* kPlateImage = povgen::kEnvironmentPlate;
inline constexpr const char* kPlateSidecar = "textures/environment_plate.inputs";
inline constexpr const char* kPlateLog = "logs/environment_plate.log";

/// Hash of everything the plate depends on: the bytes of plate.ini, plate.pov, scene.inc,
/// environment.inc and raintrace_materials.inc at the folder root (a missing file counts as
/// missing, not as empty).
std::string environment_plate_inputs_hash(const std::filesystem::path& out_dir);

/// Brings out_dir's plate up to date. Construction decides and starts; poll() or wait() finish.
/// No plate.ini: nothing to do. Plate current (image decodes at width×height and the sidecar
/// holds the inputs' hash): nothing to do. Otherwise the old plate and sidecar are removed at
/// once and POV-Ray renders plate.ini in the background (log in kPlateLog). A POV-Ray that gave
/// up before starting (povray_did_not_start) is started again, up to kPovrayStartAttempts
/// starts in all; each start rewrites the log.
class EnvironmentPlate {
 public:
  /// width, height: the frames' size (the manifest's), which the plate must have. stop: set from
  /// a signal handler; may be null. Throws std::system_error only when fork fails.
  EnvironmentPlate(std::filesystem::path out_dir, int width, int height,
                   const std::atomic<bool>* stop = nullptr);
  /// Stops a POV-Ray still running (its partial output stays in the temp folder).
  ~EnvironmentPlate();
  EnvironmentPlate(const EnvironmentPlate&) = delete;
  EnvironmentPlate& operator=(const EnvironmentPlate&) = delete;

  /// Non-blocking: true once finished, successfully or not. On success the plate is at
  /// kPlateImage with its sidecar; otherwise kPlateImage does not exist. Throws
  /// std::system_error (ENOSPC) when POV-Ray failed because the folder's disk is full.
  bool poll();
  /// Blocks (polling every 20 ms) until poll() is true; a stop request ends POV-Ray and finishes
  /// as interrupted. on_tick, when given, is called at each poll (progress displays).
  void wait(const std::function<void()>& on_tick = {});

  /// True when this object started POV-Ray (the plate was missing or stale).
  [[nodiscard]] bool started() const { return m_starts > 0; }
  [[nodiscard]] bool interrupted() const { return m_interrupted; }
  /// Empty unless finished without a plate: one line with POV-Ray's exit code, its own error
  /// lines (or why the image was rejected) and the log path; "interrupted" when stopped.
  [[nodiscard]] const std::string& problem() const { return m_problem; }

 private:
  void start_povray();
  void finish(int exit_code);
  void fail(std::string reason);

  std::filesystem::path m_out;
  int m_width;
  int m_height;
  const std::atomic<bool>* m_stop;
  std::string m_inputs_hash;
  std::unique_ptr<ChildProcess> m_process;
  int m_starts = 0;  ///< POV-Ray processes started on the plate
  bool m_done = false;
  bool m_interrupted = false;
  std::string m_problem;
};

/// The one line the renderers report when a plate failed (not when it was interrupted).
std::string environment_plate_notice(const EnvironmentPlate& plate);

}  // namespace raintrace::render
