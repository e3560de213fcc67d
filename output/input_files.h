// The files POV-Ray reads in an output folder (the shared includes, the ini files, the atlas,
// each frame's text), as raintrace last wrote or saw them. The folder is plain POV-Ray, so a
// user may edit environment.inc or a frame's text and render again: the manifest's input hashes
// were computed from what the export wrote, and without this record a frame rendered before the
// edit would still count as up to date. Checking costs a stat per file; a file is read only when
// its size or modification time differs from the record (a `touch` alone changes nothing).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace raintrace::output {

struct InputFileRecord {
  std::string path;  ///< relative to the output folder: "environment.inc", "frames/frame_0001.pov"
  std::uint64_t size = 0;
  std::int64_t mtime_ns = 0;  ///< modification time, nanoseconds of the file clock
  std::string hash;           ///< povgen::content_hash of the bytes
  bool by_hand = false;       ///< edited since raintrace wrote it (JSON "edited_by_hand")
  bool operator==(const InputFileRecord&) const = default;
};

/// The record of dir/relative as it is now; nullopt when there is no such file.
std::optional<InputFileRecord> record_input_file(const std::filesystem::path& dir,
                                                 const std::string& relative);

enum class InputFileCheck {
  same,     ///< size and modification time as recorded
  touched,  ///< another modification time, the same bytes: the record now has the new time
  edited,   ///< other bytes: the record now describes them, marked as edited by hand
  missing,  ///< no file (a render of its frame fails and says so; an export writes it again)
};

/// Compares the file with its record, and brings the record up to date with the file.
InputFileCheck check_input_file(const std::filesystem::path& dir, InputFileRecord& record);

}  // namespace raintrace::output
