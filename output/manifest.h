// manifest.json: what an output folder holds and in which state each frame's pictures are. Only
// the folder's state owner (folder_state.h) changes it; this file is the data and its JSON form.
// Written under a temporary name and renamed, so a crash never leaves a half-written manifest.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "film/develop.h"
#include "output/input_files.h"
#include "povgen/export_params.h"

namespace raintrace::output {

/// Where a frame's picture (its image or its mask) stands. JSON: the names below as strings.
enum class FrameStatus {
  exported,   ///< "exported": not rendered from the frame's current inputs (never, or they changed)
  rendering,  ///< "rendering": a POV-Ray process was started on it (a killed run leaves this)
  rendered,   ///< "rendered": the file was verified and its size and content hash recorded
  failed,     ///< "failed": POV-Ray did not produce it; `error` says why
};

const char* to_string(FrameStatus status);
/// The status named by `text`; nullopt for anything else.
std::optional<FrameStatus> parse_frame_status(std::string_view text);

/// One picture a frame renders into, and what is known about the file.
struct PictureRecord {
  std::string scene;  ///< the .pov POV-Ray renders it from: "frames/frame_0001.pov"
  std::string path;   ///< the picture: "images/frame_0001.png", relative to the output folder
  FrameStatus status = FrameStatus::exported;
  /// The frame's input_hash when the file was rendered (status rendered); else empty.
  std::string rendered_hash;
  std::uint64_t size = 0;  ///< bytes of the file as recorded (status rendered)
  std::string file_hash;   ///< povgen::content_hash of those bytes (status rendered)
  double seconds = 0.0;    ///< POV-Ray's time for it
  std::string error;       ///< why it failed (status failed), one line
};

/// A frame's developed picture (images/frame_NNNN.png): its EXR through film/. Current while
/// develop_hash is the folder's, source_hash the EXR's recorded file hash, and the file has the
/// recorded size and content hash.
struct DevelopRecord {
  std::string path;          ///< "images/frame_0001.png"
  std::string develop_hash;  ///< the develop hash it was made with; empty: not developed
  std::string source_hash;   ///< file_hash of the EXR it was developed from
  std::uint64_t size = 0;    ///< bytes of the PNG as recorded
  std::string file_hash;     ///< povgen::content_hash of those bytes
  double seconds = 0.0;      ///< develop's time for it
  std::string error;         ///< why the last develop failed, one line; empty otherwise
};

struct FrameEntry {
  int number = 0;  ///< 1-based frame number
  /// Hash of everything this frame's render reads (shared files + its own text). Empty while
  /// the frame file is being written again: such a frame cannot be up to date.
  std::string input_hash;
  /// The frame POV-Ray renders: images/frame_NNNN.exr.
  PictureRecord image;
  /// The frame developed from it: images/frame_NNNN.png.
  DevelopRecord developed;
  /// The rain mask (images/mask_NNNN.png) when the folder was exported with masks.
  std::optional<PictureRecord> mask;
};

/// What the folder was made from. A run may only add to a folder made from the same.
struct FolderIdentity {
  /// povgen::content_hash of the scene's canonical text: every key that shapes the rendered
  /// frames as loaded, develop keys left out (cli::canonical_scene_text)
  std::string scene_hash;
  std::uint64_t seed = 0;
  int width = 0;
  int height = 0;
  double fps = 0.0;
  povgen::Quality quality = povgen::Quality::preview;
  bool masks = false;  ///< frames also have rain masks (mask.ini)
  bool operator==(const FolderIdentity&) const = default;
};

/// How a folder's frames are developed: the scene's [camera] develop keys, the field of view
/// vignetting and the diffraction spikes follow, and the lens opening the spikes follow (grain and
/// sensor noise follow the identity's seed and each frame's number).
struct DevelopSpec {
  film::DevelopSettings settings;
  double fov_deg = 60.0;
  double aperture_m = 0.0;
  bool operator==(const DevelopSpec& other) const {
    return film::describe(settings) == film::describe(other.settings) && fov_deg == other.fov_deg &&
           aperture_m == other.aperture_m;
  }
};

/// The layout this raintrace writes: 2 = frames rendered as EXR and developed into PNGs. Folders
/// of format 1 (8-bit PNGs straight from POV-Ray) are not resumed.
inline constexpr int kFolderFormat = 2;

struct Manifest {
  std::string raintrace_version;
  int format = kFolderFormat;  ///< JSON "folder_format"; absent = 1
  FolderIdentity identity;
  DevelopSpec develop;
  /// Hash of the files every frame shares, as last exported (part of every input_hash).
  std::string shared_hash;
  int frame_count = 0;  ///< frames the scene has ([output] frames); 0 before the first export
  std::vector<FrameEntry> frames;  ///< ascending by number
  /// The files POV-Ray reads, as raintrace last wrote or saw them (input_files.h): a file
  /// edited by hand since changes the input hashes of the frames that read it.
  std::vector<InputFileRecord> input_files;
  /// What the MP4/GIF and the contact sheet were made from (assembly_key of the frames they
  /// show); empty when they were not made.
  std::string movie_source;
  std::string contact_sheet_source;
};

/// Digits of the frame numbers in the folder's file names ("images/frame_00001.png" → 5);
/// from frame_count (povgen::frame_digits) when no frame is listed.
int frame_digits(const Manifest& manifest);

std::string to_json(const Manifest& manifest);
/// Throws std::runtime_error naming the field when the text is not a raintrace manifest.
Manifest manifest_from_json(const std::string& json);
/// Throws std::runtime_error naming the file when it cannot be read or is not a manifest.
Manifest read_manifest(const std::filesystem::path& path);
/// Writes path via a temporary file and a rename. Throws std::system_error (with the system's
/// reason, e.g. "No space left on device") naming the file.
void write_manifest(const std::filesystem::path& path, const Manifest& manifest);

}  // namespace raintrace::output
