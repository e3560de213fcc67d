// A scene file, loaded and validated: the one place the TOML is read (toml++ stays in the .cpp).
// Every value is checked; errors name file:line:column and the key.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

#include "film/develop.h"
#include "film/diffraction_spikes.h"
#include "film/exposure.h"
#include "film/grain.h"
#include "film/sensor_noise.h"
#include "film/softness.h"
#include "film/white_balance.h"
#include "povgen/export_params.h"
#include "sim/param_table.h"
#include "sim/params.h"

namespace raintrace::cli {

/// A problem in a scene file. what() is one line: "FILE:LINE:COL: KEY: message".
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Scene {
  std::filesystem::path source;  ///< the scene file (or the name given to load_scene_string)
  std::string text;              ///< the file's bytes, for hashing into manifest.json
  /// Folder that look.environment.include_path is relative to: the scene file's folder (or the
  /// base_dir given to load_scene_string). Added by the cli owner.
  std::filesystem::path base_dir;
  int frames = 48;     ///< length of the animation
  sim::SimParams sim;  ///< camera is filled identically in sim and look
  povgen::ExportParams look;
  /// How the rendered HDR frames are developed into PNGs ([camera] exposure_ev, white_balance_k,
  /// view, look, bloom, softness, grain, sensor_noise, vignette, aperture_blades). Changing only
  /// these re-develops a folder without rendering it.
  film::DevelopSettings develop;
};

/// Scene's own key; the others are in the tables of sim/, povgen/ and below (scene_tables.h).
inline constexpr sim::Param<Scene> kSceneParams[] = {
    sim::integer("output", "frames", &Scene::frames, "frames", 1, 100000),
};

/// [camera]'s develop keys (film/develop.h gives each setting's contract). Their table sits
/// here because film/ knows nothing of scene files.
inline constexpr sim::Param<film::DevelopSettings> kDevelopParams[] = {
    sim::number("camera", "exposure_ev", &film::DevelopSettings::exposure_ev, "stops",
                sim::Range::closed(-film::kExposureLimitEv, film::kExposureLimitEv)),
    // 0 (off) or [2000, 20000]: the gap is checked with the section (scene.cpp).
    sim::number("camera", "white_balance_k", &film::DevelopSettings::white_balance_k, "K",
                sim::Range::closed(0, film::kMaxWhiteBalanceK)),
    sim::choice<&film::DevelopSettings::view>("camera", "view", film::kViewNames),
    sim::choice<&film::DevelopSettings::look>("camera", "look", film::kLookNames),
    sim::number("camera", "bloom", &film::DevelopSettings::bloom, "share of the light",
                sim::Range::closed(0, 1)),
    sim::number("camera", "softness", &film::DevelopSettings::softness, "px at 1920 wide",
                sim::Range::closed(0, film::kMaxSoftness)),
    sim::number("camera", "grain", &film::DevelopSettings::grain, "RMS at mid-grey",
                sim::Range::closed(0, film::kMaxGrain)),
    sim::number("camera", "sensor_noise", &film::DevelopSettings::sensor_noise,
                "relative RMS at mid-grey", sim::Range::closed(0, film::kMaxSensorNoise)),
    sim::number("camera", "vignette", &film::DevelopSettings::vignette, "",
                sim::Range::closed(0, 1)),
    sim::integer("camera", "aperture_blades", &film::DevelopSettings::aperture_blades, "blades", 0,
                 film::kMaxApertureBlades),
};
static_assert(sim::well_formed<film::DevelopSettings>(kDevelopParams));

/// The scene as far as it shapes the rendered (HDR) frames, as text: every key of every table
/// whose value as loaded differs from the built-in default (comments, order and spelling of the
/// file do not matter, nor does a key that a later raintrace adds while the scene leaves it at
/// its default), except the keys that do not change a rendered frame or that the folder's
/// identity holds apart: the develop keys above, `seed`, [output] frames, width, height, fps,
/// quality and [export] mask. Its hash is the scene_hash of an output folder
/// (docs/output-folder.md).
std::string canonical_scene_text(const Scene& scene);

/// Reads and validates a scene file. Throws SceneError (also for a missing/unreadable file).
Scene load_scene_file(const std::filesystem::path& path);

/// Same from text; source_name is used in messages, base_dir resolves [environment] include.
Scene load_scene_string(std::string_view toml_text, const std::string& source_name,
                        const std::filesystem::path& base_dir);

/// Sets the picture's size in pixels and what the simulation takes from it: the camera's aspect
/// and its width in pixels, by which the rain, the splashes and the ripples are drawn no finer
/// than a pixel. The loader sets [output] width and height this way; `raintrace render
/// --width/--height` must too, so that the size given on the command line makes the same frames
/// as the same size written in the scene file.
void set_image_size(Scene& scene, int width, int height);

struct FrameRange {
  int first = 1;  ///< 1-based, inclusive
  int last = 1;   ///< inclusive
};

/// Parses "--frames A-B" (or "N") against a scene of `frames` frames; empty = all frames.
/// Throws std::invalid_argument with a clear message when out of range or malformed.
FrameRange parse_frame_range(std::string_view text, int frames);

}  // namespace raintrace::cli
