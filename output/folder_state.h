// The one owner of an output folder's state. A run gets a FolderState by claiming the folder
// (export, render of a scene file) or opening it (render of an exported folder); either takes
// the folder's lock first (folder_lock.h) and decides whether this run may use the folder at
// all. From then on every change to manifest.json goes through this class: the export's, the
// renderers' and develop's transitions, and the one rule for whether a picture is up to date:
//
//   rendered    ⇔  the frame is exported (input_hash known), its picture (EXR, or mask) was
//                  rendered from that input_hash, and the file on disk has the size and content
//                  hash recorded then;
//   developed   ⇔  its EXR is rendered, and its PNG was developed from that EXR's recorded bytes
//                  with this run's develop hash (develop_hash(): the [camera] develop keys, the
//                  field of view, the seed and the display transform's response), and the PNG
//                  has the size and content hash recorded then;
//   up to date  ⇔  rendered and developed (and its mask rendered, with masks).
//
// Everything else is rendered or developed again, and the plan says why (new, inputs changed,
// interrupted, failed before, file missing/truncated/changed, develop settings changed, forced).
// A frame whose EXR is current is never rendered again for its PNG. The movie and contact sheet
// are made only from frames that are up to date at the time.
//
// Not thread-safe: one thread at a time (the local renderer takes exported frames from the
// exporter's thread through render::FrameFeed, and applies them here on its own).
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "output/folder_lock.h"
#include "output/layout.h"
#include "output/manifest.h"

namespace raintrace::output {

/// The folder holds another scene's (or another tool's) files, and this run was not told to
/// replace them. what() says what is there and how to proceed (--force, another folder).
class FolderRefused : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Why a picture is, or is not, rendered in this run.
enum class RenderReason {
  up_to_date,      ///< nothing to do
  not_exported,    ///< no current frame file (being written, or exported with other shared files)
  new_frame,       ///< exported, never rendered from these inputs
  inputs_changed,  ///< rendered from other inputs
  interrupted,     ///< a run stopped (or was killed) while POV-Ray worked on it
  failed_before,   ///< POV-Ray failed on it in an earlier run
  file_missing,    ///< recorded as rendered, but the file is gone
  file_empty,      ///< recorded as rendered, but the file has 0 bytes
  file_truncated,  ///< shorter than recorded, and no longer a whole image
  file_changed,    ///< other bytes than recorded (a whole image, or longer)
  forced,          ///< --force
};

/// "new", "inputs changed", "image truncated", …: how plans and messages word a reason.
const char* describe(RenderReason reason);

/// Whether a reason means POV-Ray has to run.
constexpr bool needs_render(RenderReason reason) {
  return reason != RenderReason::up_to_date && reason != RenderReason::not_exported;
}

/// Why a frame's PNG is, or is not, developed in this run (its EXR being rendered).
enum class DevelopReason {
  up_to_date,        ///< nothing to do
  not_rendered,      ///< the EXR is not up to date: developed once it is rendered
  new_frame,         ///< rendered, never developed from this EXR
  settings_changed,  ///< developed with another develop hash (settings, view, transform)
  failed_before,     ///< develop failed on it in an earlier run
  file_missing,      ///< recorded as developed, but the PNG is gone
  file_changed,      ///< other bytes than recorded (truncated, empty or edited)
};

/// "not developed", "develop settings changed", "picture missing", …
const char* describe(DevelopReason reason);

/// Whether a reason means develop has to run on a current EXR.
constexpr bool needs_develop(DevelopReason reason) {
  return reason != DevelopReason::up_to_date && reason != DevelopReason::not_rendered;
}

struct RenderRequest {
  bool force = false;             ///< render every exported picture again
  std::optional<FrameSpan> only;  ///< consider these frames only
};

/// What a run renders, and what it leaves and why.
struct RenderPlan {
  std::vector<int> images;    ///< frames whose EXR is rendered (and then developed), ascending
  std::vector<int> masks;     ///< frames whose mask is rendered (folders exported with masks)
  std::vector<int> develops;  ///< frames whose EXR is current and whose PNG is developed again
  int frames = 0;             ///< frames considered
  int up_to_date = 0;         ///< frames with nothing to render or develop
  /// Pictures (images and masks) by reason, including up_to_date and not_exported.
  std::map<RenderReason, int> reasons;
  /// Frames to develop without rendering, by reason.
  std::map<DevelopReason, int> develop_reasons;
  /// "3 to render: 2 new, 1 image truncated; 5 to develop: 5 develop settings changed; 20 frames
  /// up to date".
  [[nodiscard]] std::string summary() const;
};

/// What claiming did to the folder, for the user: empty when the folder was new or simply
/// resumed; otherwise one line ("replaced a folder made from another scene: 24 frames removed").
struct ClaimNote {
  std::string text;
};

class FolderState {
 public:
  /// For a run that exports into dir. Creates dir (std::system_error naming dir when it cannot),
  /// takes its lock (FolderBusy) and checks what is there:
  ///   - nothing (or only a lock file): a new folder, marked as raintrace's at once;
  ///   - a manifest of the same identity: resumed as it is;
  ///   - a manifest of another identity (another scene, seed, size, fps, quality or masks), of
  ///     an older folder format, or files but no raintrace manifest: FolderRefused, unless
  ///     `force`. With force, every
  ///     file the old manifest records (frame files, images, masks, movie, contact sheet, plate,
  ///     logs) is removed and the folder starts anew; files it does not record are never
  ///     touched (in a folder raintrace did not make, same-named files get overwritten).
  /// `command` is recorded in the lock for whoever finds the folder busy.
  static FolderState claim(const std::filesystem::path& dir, const FolderIdentity& identity,
                           bool force, const std::string& command, ClaimNote* note = nullptr);

  /// Both claim() (when it resumes) and open() adopt pictures rendered by hand: a frame's
  /// picture that POV-Ray wrote at its final name outside raintrace (`povray scene.ini` in the
  /// folder, on a farm) counts as rendered when it decodes completely at the frame size and is
  /// newer than every file POV-Ray read for it (the frame's .pov files and the shared files:
  /// make's rule). Its PNG is then developed like any other.
  ///
  /// Before that, both notice the files POV-Ray reads that were edited since raintrace wrote
  /// them (input_files.h: a shared include, a frame's text): the frames that read such a file
  /// count as "inputs changed", and edited_inputs() names the files for the user.
  ///
  /// For a run that renders an already exported folder: takes the lock (FolderBusy) and reads
  /// the manifest. Throws FolderRefused when dir holds no raintrace manifest, or one of an older
  /// folder format.
  static FolderState open(const std::filesystem::path& dir, const std::string& command);

  // --- Export transitions ------------------------------------------------------------------

  /// Before an export writes any frame file. Records the shared files' hash and the scene's
  /// frame count: frames past frame_count are removed with their files (a shorter scene), and
  /// when the shared files changed, frames outside `range` lose their input_hash (their files
  /// no longer match: they need exporting again). Frames in `range` lose theirs until
  /// frame_exported() (a killed export never leaves an entry vouching for a file it was
  /// rewriting). Saves.
  void begin_export(const std::string& shared_hash, FrameSpan range, int frame_count);
  /// The frame's files are complete at their final names, with this input hash. A picture
  /// rendered from other inputs becomes "exported" again. Does not save (save() per batch).
  void frame_exported(int number, const std::string& input_hash);

  // --- Render transitions --------------------------------------------------------------------

  /// POV-Ray starts on these pictures. In memory only: the next save records it.
  void rendering(Pass pass, FrameSpan span);
  /// The picture is at its final name, verified complete: records its size and content hash
  /// and the input hash it was made from. Saves.
  void rendered(Pass pass, int number, double seconds);
  /// POV-Ray did not make it; `error` is one line. Saves.
  void failed(Pass pass, int number, const std::string& error);

  // --- Develop ---------------------------------------------------------------------------------

  /// Records how the frames are developed (the scene's [camera] develop keys). PNGs developed
  /// otherwise stop being current once set_develop_hash() gives the new hash. Saves.
  void set_develop(const DevelopSpec& spec);
  /// The develop hash of this run (develop_hash() of the manifest's DevelopSpec): what a PNG
  /// must have been developed with to be current. Until it is set, no PNG is current.
  void set_develop_hash(std::string hash);
  [[nodiscard]] const std::string& develop_hash() const { return m_develop_hash; }
  /// The frame's PNG is at developed_image_name(), verified complete, developed from the EXR
  /// now recorded with this run's develop hash: records its size and content hash. Saves.
  void developed(int number, double seconds);
  /// Develop failed on it; `error` is one line. Saves.
  void develop_failed(int number, const std::string& error);

  // --- Decisions -----------------------------------------------------------------------------

  /// The rule above for one picture (reads the file to check it; decodes it only when its bytes
  /// are not the recorded ones, to tell truncated from changed). A frame or mask the manifest
  /// does not have is not_exported.
  [[nodiscard]] RenderReason decide(Pass pass, int number, bool force) const;
  /// The develop rule for the frame's PNG (reads the PNG to check it).
  [[nodiscard]] DevelopReason decide_develop(int number) const;
  /// decide() over the frames in request.only (all when unset), images and, for a folder
  /// exported with masks, masks; decide_develop() for frames whose EXR stays.
  [[nodiscard]] RenderPlan plan(const RenderRequest& request) const;
  /// Frames that are rendered and developed right now, ascending: what the movie and contact
  /// sheet may show.
  [[nodiscard]] std::vector<int> verified_frames() const;

  /// Writes manifest.json (std::system_error with the reason when it cannot).
  void save() const;
  /// Records what the movie or the contact sheet was made from (assembly_key()); saves.
  void set_movie_source(const std::string& key);
  void set_contact_sheet_source(const std::string& key);

  [[nodiscard]] const Manifest& manifest() const { return m_manifest; }
  [[nodiscard]] const std::filesystem::path& dir() const { return m_dir; }
  /// This run's lock record: its run_id is what Slurm tasks show to work under it.
  [[nodiscard]] const LockHolder& holder() const { return m_lock.holder(); }
  /// Digits of the frame numbers in this folder's file names.
  [[nodiscard]] int digits() const;
  /// The frame's entry; nullptr when the manifest has none.
  [[nodiscard]] const FrameEntry* find(int number) const;
  /// Files POV-Ray reads that were edited since the last run saw them, found when this run
  /// claimed or opened the folder ("environment.inc", "frames/frame_0003.pov").
  [[nodiscard]] const std::vector<std::string>& newly_edited_inputs() const {
    return m_edited_inputs;
  }
  /// Files POV-Ray reads that are not as raintrace wrote them: edited by hand in this run's
  /// sight or an earlier one's (an export writes the scene's own over those it exports).
  [[nodiscard]] std::vector<std::string> hand_edited_inputs() const;

 private:
  FolderState(FolderLock lock, std::filesystem::path dir, Manifest manifest);
  FrameEntry* find_mutable(int number);
  PictureRecord* picture(Pass pass, int number);
  void adopt_unhashed_pictures();
  void adopt_rendered_by_hand();
  void notice_hand_edits();
  /// Records these files' size, time and hash as they are now (input_files.h).
  void record_inputs(const std::vector<std::string>& paths);
  DevelopReason decide_develop(int number, RenderReason image) const;

  FolderLock m_lock;
  std::filesystem::path m_dir;
  Manifest m_manifest;
  std::string m_develop_hash;
  std::vector<std::string> m_edited_inputs;
};

/// The develop hash: the settings and field of view of `spec`, the seed, and `response` (the
/// display transform's film::DisplayTransform::response() for the spec's view and look).
std::string develop_hash(const DevelopSpec& spec, std::uint64_t seed,
                         const film::RgbImage& response);

/// A key for a set of verified frames: their numbers and their PNGs' content hashes. The
/// manifest keeps the key the movie and the contact sheet were made from, so they are made
/// again exactly when the frames they show changed.
std::string assembly_key(const FolderState& folder, const std::vector<int>& frames);

}  // namespace raintrace::output
