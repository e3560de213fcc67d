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

struct FrameEntry {
  int number = 0;  ///< 1-based frame number
  /// Hash of everything this frame's render reads (shared files + its own text). Empty while
  /// the frame file is being written again: such a frame cannot be up to date.
  std::string input_hash;
  PictureRecord image;
  /// The rain mask (images/mask_NNNN.png) when the folder was exported with masks.
  std::optional<PictureRecord> mask;
};

/// What the folder was made from. A run may only add to a folder made from the same.
struct FolderIdentity {
  std::string scene_hash;  ///< povgen::content_hash of the scene file's bytes
  std::uint64_t seed = 0;
  int width = 0;
  int height = 0;
  double fps = 0.0;
  povgen::Quality quality = povgen::Quality::preview;
  bool masks = false;  ///< frames also have rain masks (mask.ini)
  bool operator==(const FolderIdentity&) const = default;
};

struct Manifest {
  std::string raintrace_version;
  FolderIdentity identity;
  /// Hash of the files every frame shares, as last exported (part of every input_hash).
  std::string shared_hash;
  int frame_count = 0;  ///< frames the scene has ([output] frames); 0 before the first export
  std::vector<FrameEntry> frames;  ///< ascending by number
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
