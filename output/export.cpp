// The export: simulate, write the shared files, then every frame of the range, each handed to
// the folder's state (or to the hook) once its files are in place.
#include "output/export.h"

#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>

#include "povgen/content_hash.h"
#include "povgen/frame_text.h"
#include "povgen/frame_values.h"
#include "povgen/output_folder.h"
#include "povgen/scene_files.h"
#include "sim/lamp_rain.h"
#include "sim/world.h"

namespace raintrace::output {
namespace {

int writer_threads(int requested) {
  if (requested > 0) return requested;
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

/// The frames scene.ini renders: this export's range, widened by the frames earlier exports
/// left in the folder that join it without a gap, so that `povray scene.ini` renders frames
/// that all exist (after exports in order, every frame the folder holds).
povgen::FrameSubset frames_in_folder(const Manifest& manifest, FrameSpan range, int frame_count) {
  std::set<int> earlier;
  for (const FrameEntry& frame : manifest.frames) {
    if (frame.number >= 1 && frame.number <= frame_count) earlier.insert(frame.number);
  }
  povgen::FrameSubset frames{range.first, range.last};
  while (earlier.count(frames.first - 1) != 0) --frames.first;
  while (earlier.count(frames.last + 1) != 0) ++frames.last;
  return frames;
}

}  // namespace

FolderIdentity identity_of(std::string_view canonical_scene, const SceneToExport& scene) {
  FolderIdentity id;
  id.scene_hash = povgen::content_hash(canonical_scene);
  id.seed = scene.sim.seed;
  id.width = scene.look.width;
  id.height = scene.look.height;
  id.fps = scene.look.fps;
  id.quality = scene.look.quality;
  id.masks = scene.look.mask;
  return id;
}

bool export_frames(FolderState& folder, const SceneToExport& scene, FrameSpan range,
                   const ExportHooks& hooks) {
  if (range.first < 1 || range.last < range.first || range.last > scene.frames) {
    throw std::invalid_argument("export: frame range " + std::to_string(range.first) + "-" +
                                std::to_string(range.last) + " is outside 1-" +
                                std::to_string(scene.frames));
  }
  const povgen::ExportParams& look = scene.look;
  const std::filesystem::path& out_dir = folder.dir();
  const std::string shared_hash =
      povgen::write_shared_files(out_dir, look, scene.frames, scene.scene_dir,
                                 frames_in_folder(folder.manifest(), range, scene.frames));
  folder.begin_export(shared_hash, range, scene.frames);
  if (hooks.on_shared_files) hooks.on_shared_files();

  auto stopped = [&] { return hooks.stop != nullptr && hooks.stop->load(); };
  // Without a receiver the frames are recorded here, and the manifest saved however this ends
  // (stopped, or a frame that could not be written): every frame file finished is vouched for.
  struct SaveAtEnd {
    FolderState* folder;
    ~SaveAtEnd() {
      if (folder == nullptr) return;
      try {
        folder->save();
      } catch (...) {  // already failing (a full disk): the error on the way out says why
      }
    }
  } save_at_end{hooks.on_frame ? nullptr : &folder};

  const int digits = povgen::frame_digits(scene.frames);
  const int threads = writer_threads(scene.sim.threads);
  const int total = range.count();
  povgen::FrameValues values;  // reused: its memory stays mapped from frame to frame
  int n = 1;
  try {
    sim::World world(scene.sim, hooks.stop);
    sim::LampRain lamp_rain(scene.sim, hooks.stop);
    for (; n <= range.last && !stopped(); ++n) {
      // Frame n shows the world at (n − 1)/fps: the state depends on every earlier frame, so
      // frames before the range are simulated but not written.
      world.advance_to((n - 1) / look.fps);
      lamp_rain.advance_to((n - 1) / look.fps);
      if (n < range.first) continue;
      sim::Frame frame = world.snapshot(n);
      lamp_rain.add_drops(frame.drops);
      const std::string name = frame_scene_name(Pass::image, n, digits);
      povgen::build_frame_values(frame, look, values, povgen::StreakAtlasLayout{}, threads);
      // Everything POV-Ray reads for this frame: the shared files (scene.inc, includes, atlas,
      // ini) and the frame's own text, hashed while it streams to disk.
      ExportedFrame exported{
          n, povgen::write_frame_file(out_dir / name, values, shared_hash, threads)};
      if (look.mask) {
        povgen::write_file_atomic(out_dir / frame_scene_name(Pass::mask, n, digits),
                                  povgen::mask_text(name));
      }
      if (hooks.on_frame) {
        hooks.on_frame(std::move(exported));
      } else {
        folder.frame_exported(n, exported.input_hash);
      }
      if (hooks.on_progress) hooks.on_progress({n - range.first + 1, total});
    }
  } catch (const sim::Cancelled&) {
    return false;
  }
  return n > range.last;
}

}  // namespace raintrace::output
