// manifest.json: what an output folder holds and in which state each frame is.
// povgen writes it at export; render/ updates frame status and timings. Always written to a
// temporary name and renamed, so a crash never leaves a half-written manifest.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace raintrace::povgen {

struct FrameEntry {
  int number = 0;                   ///< 1-based frame number
  std::string scene;                ///< "frames/frame_0001.pov", relative to the output folder
  std::string image;                ///< "images/frame_0001.png", relative to the output folder
  std::string input_hash;           ///< hash of everything this frame's render depends on
  std::string status = "exported";  ///< "exported" | "rendered" | "failed"
  std::string rendered_hash;        ///< input_hash of the inputs the existing image was made from
  double render_seconds = 0.0;
  std::string error;  ///< POV-Ray's error line when status == "failed"
};

struct Manifest {
  std::string raintrace_version;
  std::string scene_hash;  ///< hash of the scene file's bytes
  std::uint64_t seed = 0;
  int width = 0;
  int height = 0;
  double fps = 0.0;
  std::string quality;  ///< "preview" | "final"
  std::vector<FrameEntry> frames;
};

std::string to_json(const Manifest& manifest);
Manifest manifest_from_json(const std::string& json);  ///< throws std::runtime_error
Manifest read_manifest(const std::filesystem::path& path);
/// Writes path.tmp then renames it over path.
void write_manifest(const std::filesystem::path& path, const Manifest& manifest);

/// 64-bit FNV-1a of bytes, as 16 hex digits: cheap, stable across platforms and runs.
std::string content_hash(std::string_view bytes);

/// content_hash() fed piece by piece (added by the export owner): hashing a frame while it
/// streams to disk gives the same digits as hashing its whole text at once.
class ContentHasher {
 public:
  void update(std::string_view bytes);
  [[nodiscard]] std::string hex() const;

 private:
  std::uint64_t m_hash = 0xcbf29ce484222325ULL;  // FNV-1a 64-bit offset basis
};

}  // namespace raintrace::povgen
