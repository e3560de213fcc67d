// Simulate a scene and write its output folder: the thin orchestration over sim::World and
// povgen's three parts (values, text, files). Shared by `raintrace export` and `render`.
#include "cli/export_pipeline.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>

#include "povgen/frame_text.h"
#include "povgen/frame_values.h"
#include "povgen/manifest.h"
#include "povgen/output_folder.h"
#include "sim/world.h"

namespace raintrace::cli {
namespace {

const char* quality_name(povgen::Quality quality) {
  return quality == povgen::Quality::final ? "final" : "preview";
}

int writer_threads(int requested) {
  if (requested > 0) return requested;
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

/// The previous manifest's frames by number, if there is a readable one; a damaged manifest
/// is replaced (its frames will simply render again).
std::map<int, povgen::FrameEntry> previous_frames(const std::filesystem::path& path) {
  std::map<int, povgen::FrameEntry> frames;
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return frames;
  try {
    for (auto& f : povgen::read_manifest(path).frames) frames[f.number] = std::move(f);
  } catch (const std::runtime_error&) {
    frames.clear();
  }
  return frames;
}

/// The frames scene.ini renders: this export's range, widened by the frames earlier exports
/// left in the folder that join it without a gap, so `povray scene.ini` renders frames that
/// all exist (and, after exports in order, all the folder holds).
povgen::FrameSubset frames_in_folder(const std::map<int, povgen::FrameEntry>& earlier,
                                     const FrameRange& range) {
  povgen::FrameSubset frames{range.first, range.last};
  for (auto it = earlier.lower_bound(range.first); it != earlier.begin();) {
    if ((--it)->first != frames.first - 1) break;
    frames.first = it->first;
  }
  for (auto it = earlier.upper_bound(range.last); it != earlier.end(); ++it) {
    if (it->first != frames.last + 1) break;
    frames.last = it->first;
  }
  return frames;
}

}  // namespace

void export_scene(const Scene& scene, const FrameRange& range, const std::filesystem::path& out_dir,
                  const std::function<void(const ExportProgress&)>& on_progress) {
  ExportHooks hooks;
  hooks.on_progress = on_progress;
  export_scene(scene, range, out_dir, hooks);
}

void export_scene(const Scene& scene, const FrameRange& range, const std::filesystem::path& out_dir,
                  const ExportHooks& hooks) {
  if (range.first < 1 || range.last < range.first || range.last > scene.frames) {
    throw std::invalid_argument("export: frame range " + std::to_string(range.first) + "-" +
                                std::to_string(range.last) + " is outside 1-" +
                                std::to_string(scene.frames));
  }
  const povgen::ExportParams& look = scene.look;
  const std::filesystem::path scene_dir =
      scene.base_dir.empty() ? scene.source.parent_path() : scene.base_dir;
  const std::filesystem::path manifest_path = out_dir / "manifest.json";
  std::map<int, povgen::FrameEntry> entries = previous_frames(manifest_path);
  for (auto it = entries.begin(); it != entries.end();) {
    it = it->first > scene.frames || it->first < 1 ? entries.erase(it) : std::next(it);
  }
  const std::string shared_hash = povgen::write_shared_files(out_dir, look, scene.frames, scene_dir,
                                                             frames_in_folder(entries, range));

  povgen::Manifest manifest;
  manifest.raintrace_version = RAINTRACE_VERSION;
  manifest.scene_hash = povgen::content_hash(scene.text);
  manifest.seed = scene.sim.seed;
  manifest.width = look.width;
  manifest.height = look.height;
  manifest.fps = look.fps;
  manifest.quality = quality_name(look.quality);
  // Before any frame file is replaced: the frames about to be rewritten lose their input_hash,
  // so if this run is killed halfway no entry vouches for a file it no longer describes (a
  // frame without input_hash is never up to date). Their render state stays for the next run.
  for (const auto& [number, entry] : entries) {
    manifest.frames.push_back(entry);
    if (number >= range.first && number <= range.last) manifest.frames.back().input_hash.clear();
  }
  povgen::write_manifest(manifest_path, manifest);
  if (hooks.on_shared_files) hooks.on_shared_files();
  auto stopped = [&] { return hooks.stop != nullptr && hooks.stop->load(); };

  const int digits = povgen::frame_digits(scene.frames);
  const int threads = writer_threads(scene.sim.threads);
  const ExportProgress total{0, range.last - range.first + 1};
  povgen::FrameValues values;  // reused: its memory stays mapped from frame to frame
  sim::World world(scene.sim);
  for (int n = 1; n <= range.last && !stopped(); ++n) {
    // Frame n shows the world at (n − 1)/fps: the state depends on every earlier frame, so
    // frames before the range are simulated but not written.
    world.advance_to((n - 1) / look.fps);
    if (n < range.first) continue;
    const sim::Frame frame = world.snapshot(n);
    const std::string name = povgen::frame_file_name("frame", n, digits, ".pov");
    povgen::build_frame_values(frame, look, values, povgen::StreakAtlasLayout{}, threads);
    povgen::FrameEntry entry;
    entry.number = n;
    entry.scene = "frames/" + name;
    entry.image = "images/" + povgen::frame_file_name("frame", n, digits, ".png");
    // Everything POV-Ray reads for this frame: the shared files (scene.inc, includes, atlas,
    // ini) and the frame's own text, hashed while it streams to disk.
    entry.input_hash =
        povgen::write_frame_file(out_dir / "frames" / name, values, shared_hash, threads);
    if (look.mask) {
      povgen::write_file_atomic(
          out_dir / "frames" / povgen::frame_file_name("mask", n, digits, ".pov"),
          povgen::mask_text("frames/" + name));
    }
    const auto old = entries.find(n);
    if (old != entries.end() &&
        (old->second.input_hash == entry.input_hash ||
         (old->second.status == "rendered" && old->second.rendered_hash == entry.input_hash))) {
      // Unchanged inputs (also after an interrupted run cleared input_hash): keep "rendered"
      // and its timings.
      const std::string hash = entry.input_hash;
      entry = old->second;
      entry.input_hash = hash;
      entry.scene = "frames/" + name;
    }
    entries[n] = entry;
    if (hooks.on_frame) hooks.on_frame(entry);
    if (hooks.on_progress) hooks.on_progress({n - range.first + 1, total.frames_total});
  }
  if (hooks.on_frame) return;  // the receiver owns manifest.json now

  manifest.frames.clear();
  for (auto& [number, entry] : entries) manifest.frames.push_back(std::move(entry));
  povgen::write_manifest(manifest_path, manifest);
}

}  // namespace raintrace::cli
