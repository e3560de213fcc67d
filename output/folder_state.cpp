// The output folder's state: claiming, the transitions and the up-to-date rule (folder_state.h).
#include "output/folder_state.h"

#include <fmt/core.h>
#include <algorithm>
#include <map>
#include <system_error>
#include <utility>

#include "output/image_check.h"
#include "povgen/content_hash.h"
#include "povgen/frame_text.h"
#include "povgen/ground_scene.h"

namespace raintrace::output {
namespace {

namespace fs = std::filesystem;

// What every frame's render reads besides its own .pov files (povgen::write_shared_files);
// the ground's include and mask with puddles only.
constexpr const char* kSharedInputs[] = {"scene.ini",
                                         "scene.pov",
                                         "scene.inc",
                                         "environment.inc",
                                         "raintrace_materials.inc",
                                         "raintrace_ground.inc",
                                         "textures/streak_atlas.png",
                                         "textures/puddle_mask.png",
                                         "mask.ini",
                                         "mask.pov"};

std::string short_hash(const std::string& hash) {
  return hash.empty() ? std::string{"none"} : hash.substr(0, 8) + "…";
}

// What differs between the folder's identity and this run's, worded "X there, Y here".
std::vector<std::string> differences(const FolderIdentity& there, const FolderIdentity& here) {
  std::vector<std::string> out;
  if (there.seed != here.seed)
    out.push_back(fmt::format("seed {} there, {} here", there.seed, here.seed));
  if (there.width != here.width || there.height != here.height) {
    out.push_back(fmt::format("size {}x{} there, {}x{} here", there.width, there.height, here.width,
                              here.height));
  }
  if (there.fps != here.fps)
    out.push_back(fmt::format("fps {} there, {} here", there.fps, here.fps));
  if (there.quality != here.quality) {
    out.push_back(fmt::format("quality {} there, {} here", povgen::quality_name(there.quality),
                              povgen::quality_name(here.quality)));
  }
  if (there.masks != here.masks) {
    out.push_back(fmt::format("masks {} there, {} here", there.masks ? "on" : "off",
                              here.masks ? "on" : "off"));
  }
  return out;
}

std::string join(const std::vector<std::string>& parts, const char* separator) {
  std::string out;
  for (const auto& p : parts) out += (out.empty() ? "" : separator) + p;
  return out;
}

// Anything in dir besides what a killed first claim may leave (the lock file, a manifest that
// was still being written)?
bool holds_other_files(const fs::path& dir) {
  for (const auto& entry : fs::directory_iterator(dir)) {
    const auto name = entry.path().filename().string();
    if (name != kLockFile && name != std::string{kManifest} + ".tmp") return true;
  }
  return false;
}

void remove_file(const fs::path& dir, const std::string& relative) {
  if (relative.empty()) return;
  // Recorded paths are raintrace's own relative names; anything else is not ours to delete.
  const fs::path path{relative};
  if (path.is_absolute() || relative.find("..") != std::string::npos) return;
  std::error_code ignored;
  fs::remove(dir / path, ignored);
}

// The files POV-Ray reads for this frame alone: its .pov files and, with puddles, its ripple
// map (written beside frames/ before the frame's text, which names it).
std::vector<std::string> frame_inputs(const FrameEntry& f) {
  std::vector<std::string> files{f.image.scene};
  if (f.mask) files.push_back(f.mask->scene);
  files.push_back(povgen::ripple_map_name(f.number));
  return files;
}

bool reads(const FrameEntry& f, const std::string& path) {
  const auto files = frame_inputs(f);
  return std::find(files.begin(), files.end(), path) != files.end();
}

// Removes the files raintrace wrote for a frame: its .pov files, its EXR, PNG, mask and ripple
// map.
void remove_frame_files(const fs::path& dir, const FrameEntry& f) {
  for (const std::string& input : frame_inputs(f)) remove_file(dir, input);
  for (const PictureRecord* p : {&f.image, f.mask ? &*f.mask : nullptr}) {
    if (p != nullptr) remove_file(dir, p->path);
  }
  remove_file(dir, f.developed.path);
}

// Removes every file the manifest records: frame files, pictures, movie and contact sheet.
// Returns how many frames it listed.
int remove_recorded_files(const fs::path& dir, const Manifest& m) {
  for (const FrameEntry& f : m.frames) remove_frame_files(dir, f);
  for (const char* name : {kMovie, kGif, kContactSheet}) remove_file(dir, name);
  return static_cast<int>(m.frames.size());
}

// A frame's develop record with nothing developed: only where its PNG goes.
DevelopRecord fresh_develop_record(const std::string& path) {
  DevelopRecord d;
  d.path = path;
  return d;
}

PictureRecord new_picture(Pass pass, int number, int digits) {
  PictureRecord p;
  p.scene = frame_scene_name(pass, number, digits);
  p.path = final_image_name(pass, number, digits);
  return p;
}

}  // namespace

const char* describe(DevelopReason reason) {
  switch (reason) {
    case DevelopReason::up_to_date:
      return "up to date";
    case DevelopReason::not_rendered:
      return "not rendered";
    case DevelopReason::new_frame:
      return "not developed";
    case DevelopReason::settings_changed:
      return "develop settings changed";
    case DevelopReason::failed_before:
      return "develop failed before";
    case DevelopReason::file_missing:
      return "picture missing";
    case DevelopReason::file_changed:
      return "picture changed";
  }
  return "?";
}

const char* describe(RenderReason reason) {
  switch (reason) {
    case RenderReason::up_to_date:
      return "up to date";
    case RenderReason::not_exported:
      return "not exported";
    case RenderReason::new_frame:
      return "new";
    case RenderReason::inputs_changed:
      return "inputs changed";
    case RenderReason::interrupted:
      return "interrupted";
    case RenderReason::failed_before:
      return "failed before";
    case RenderReason::file_missing:
      return "image missing";
    case RenderReason::file_empty:
      return "image empty";
    case RenderReason::file_truncated:
      return "image truncated";
    case RenderReason::file_changed:
      return "image changed";
    case RenderReason::forced:
      return "forced";
  }
  return "?";
}

std::string RenderPlan::summary() const {
  std::vector<std::string> why;
  int to_render = 0;
  for (const auto& [reason, count] : reasons) {
    if (!needs_render(reason)) continue;
    to_render += count;
    why.push_back(fmt::format("{} {}", count, describe(reason)));
  }
  std::string out = fmt::format("{} to render", to_render);
  if (!masks.empty()) out += fmt::format(" ({} images, {} masks)", images.size(), masks.size());
  if (!why.empty()) out += ": " + join(why, ", ");
  if (!develops.empty()) {
    std::vector<std::string> develop_why;
    for (const auto& [reason, count] : develop_reasons) {
      develop_why.push_back(fmt::format("{} {}", count, describe(reason)));
    }
    out += fmt::format("; {} to develop only: {}", develops.size(), join(develop_why, ", "));
  }
  out += fmt::format("; {} frames up to date", up_to_date);
  const auto missing = reasons.find(RenderReason::not_exported);
  if (missing != reasons.end()) {
    out += fmt::format("; {} not exported (the scene's files changed since: export them again)",
                       missing->second);
  }
  return out;
}

FolderState::FolderState(FolderLock lock, fs::path dir, Manifest manifest)
    : m_lock{std::move(lock)}, m_dir{std::move(dir)}, m_manifest{std::move(manifest)} {
  std::sort(m_manifest.frames.begin(), m_manifest.frames.end(),
            [](const auto& a, const auto& b) { return a.number < b.number; });
}

FolderState FolderState::claim(const fs::path& dir, const FolderIdentity& identity, bool force,
                               const std::string& command, ClaimNote* note) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error) throw std::system_error(error, "cannot create output folder " + dir.string());
  FolderLock lock{dir, command};
  const fs::path manifest_path = dir / kManifest;
  Manifest fresh;
  fresh.raintrace_version = RAINTRACE_VERSION;
  fresh.identity = identity;
  auto start_anew = [&](std::string text) {
    if (note != nullptr) note->text = std::move(text);
    FolderState state{std::move(lock), dir, fresh};
    state.save();  // marks the folder as raintrace's before anything else is written
    return state;
  };

  if (!fs::exists(manifest_path)) {
    if (!holds_other_files(dir)) return start_anew("");
    if (!force) {
      throw FolderRefused(fmt::format(
          "{} is not empty and raintrace did not make it (no {}): its files could be "
          "overwritten. Use --force to write into it anyway, or choose a new or empty folder",
          dir.string(), kManifest));
    }
    return start_anew(
        fmt::format("--force: writing into {}, which raintrace did not make", dir.string()));
  }

  Manifest old;
  try {
    old = read_manifest(manifest_path);
  } catch (const std::system_error&) {
    throw;
  } catch (const std::runtime_error& e) {
    if (!force) {
      throw FolderRefused(fmt::format(
          "{} has a {} raintrace cannot use ({}). Use --force to replace it, or choose a new "
          "or empty folder",
          dir.string(), kManifest, e.what()));
    }
    return start_anew(
        fmt::format("--force: replaced the unreadable {} of {}", kManifest, dir.string()));
  }
  if (old.format < kFolderFormat) {
    if (!force) {
      throw FolderRefused(fmt::format(
          "{} was made by an older raintrace (folder format {}: 8-bit PNG frames without EXR). "
          "Use --force to replace its frames, or choose another output folder",
          dir.string(), old.format));
    }
    const int removed = remove_recorded_files(dir, old);
    return start_anew(fmt::format("--force: replaced {} frames of an older raintrace in {}",
                                  removed, dir.string()));
  }
  if (old.identity == identity) {
    FolderState state{std::move(lock), dir, std::move(old)};
    state.adopt_unhashed_pictures();
    state.notice_hand_edits();
    state.adopt_rendered_by_hand();
    return state;
  }
  const bool other_scene = old.identity.scene_hash != identity.scene_hash;
  const std::string what =
      other_scene
          ? fmt::format("another scene (scene hash {} there, {} here)",
                        short_hash(old.identity.scene_hash), short_hash(identity.scene_hash))
          : fmt::format("this scene with other settings ({})",
                        join(differences(old.identity, identity), ", "));
  if (!force) {
    throw FolderRefused(
        fmt::format("{} holds {} frames of {}: adding this run's would mix the two. Use --force "
                    "to replace them (their files and images are deleted), or choose another "
                    "output folder",
                    dir.string(), old.frames.size(), what));
  }
  const int removed = remove_recorded_files(dir, old);
  return start_anew(
      fmt::format("--force: replaced {} frames of {} in {}", removed, what, dir.string()));
}

FolderState FolderState::open(const fs::path& dir, const std::string& command) {
  if (!fs::is_directory(dir)) {
    throw FolderRefused(fmt::format("{} is not a folder", dir.string()));
  }
  FolderLock lock{dir, command};
  if (!fs::exists(dir / kManifest)) {
    throw FolderRefused(fmt::format(
        "{} is not an exported raintrace folder (no {}): give the scene file, or export it "
        "first with `raintrace export SCENE.toml -o {}`",
        dir.string(), kManifest, dir.string()));
  }
  Manifest m;
  try {
    m = read_manifest(dir / kManifest);
  } catch (const std::system_error&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw FolderRefused(
        fmt::format("{}: raintrace cannot use this folder: {}", dir.string(), e.what()));
  }
  if (m.format < kFolderFormat) {
    throw FolderRefused(fmt::format(
        "{} was made by an older raintrace (folder format {}: 8-bit PNG frames without EXR): "
        "render its scene file into it with --force, or into another folder",
        dir.string(), m.format));
  }
  FolderState state{std::move(lock), dir, std::move(m)};
  state.adopt_unhashed_pictures();
  state.notice_hand_edits();
  state.adopt_rendered_by_hand();
  return state;
}

void FolderState::adopt_unhashed_pictures() {
  // Manifests from before content hashes: a picture recorded as rendered from the current
  // inputs is checked by decoding it once, and its size and hash are recorded from then on.
  bool changed = false;
  for (FrameEntry& f : m_manifest.frames) {
    for (PictureRecord* p : {&f.image, f.mask ? &*f.mask : nullptr}) {
      if (p == nullptr || p->status != FrameStatus::rendered || !p->file_hash.empty()) continue;
      const auto facts = file_facts(m_dir / p->path);
      if (facts && p->rendered_hash == f.input_hash &&
          image_is_complete(m_dir / p->path, m_manifest.identity.width,
                            m_manifest.identity.height)) {
        p->size = facts->size;
        p->file_hash = facts->hash;
      } else {
        p->status = FrameStatus::exported;
      }
      changed = true;
    }
  }
  if (changed) save();
}

void FolderState::notice_hand_edits() {
  // A shared file edited changes every frame's inputs, a frame's own text only that frame's.
  // Each input hash it changes is chained with the edit (the file and its new bytes' hash), so
  // a picture rendered before counts as "inputs changed"; and so is the shared hash, so the
  // next export, which writes raintrace's own files back, finds them changed and every frame
  // is exported again.
  std::string shared_edits;
  std::map<int, std::string> frame_edits;
  bool changed = false;
  for (InputFileRecord& r : m_manifest.input_files) {
    const InputFileCheck check = check_input_file(m_dir, r);
    changed = changed || check == InputFileCheck::touched || check == InputFileCheck::edited;
    if (check != InputFileCheck::edited) continue;
    m_edited_inputs.push_back(r.path);
    const std::string edit = r.path + '\0' + r.hash + '\0';
    const auto reader = std::find_if(m_manifest.frames.begin(), m_manifest.frames.end(),
                                     [&](const FrameEntry& f) { return reads(f, r.path); });
    if (reader != m_manifest.frames.end()) {
      frame_edits[reader->number] += edit;
    } else {
      shared_edits += edit;
    }
  }
  const auto chain = [](std::string& hash, const std::string& edits) {
    if (!hash.empty() && !edits.empty()) hash = povgen::content_hash(hash + '\0' + edits);
  };
  chain(m_manifest.shared_hash, shared_edits);
  for (FrameEntry& f : m_manifest.frames) {
    chain(f.input_hash, shared_edits);
    const auto own = frame_edits.find(f.number);
    if (own != frame_edits.end()) chain(f.input_hash, own->second);
  }
  if (changed) save();
}

std::vector<std::string> FolderState::hand_edited_inputs() const {
  std::vector<std::string> paths;
  for (const InputFileRecord& r : m_manifest.input_files) {
    if (r.by_hand) paths.push_back(r.path);
  }
  return paths;
}

void FolderState::record_inputs(const std::vector<std::string>& paths) {
  auto& records = m_manifest.input_files;
  for (const std::string& path : paths) {
    const auto it = std::find_if(records.begin(), records.end(),
                                 [&](const InputFileRecord& r) { return r.path == path; });
    auto now = record_input_file(m_dir, path);
    if (it == records.end()) {
      if (now) records.push_back(std::move(*now));
    } else if (now) {
      *it = std::move(*now);
    } else {
      records.erase(it);
    }
  }
}

void FolderState::adopt_rendered_by_hand() {
  const auto mtime = [this](const std::string& relative) {
    std::error_code error;
    const auto t = fs::last_write_time(m_dir / relative, error);
    return error ? fs::file_time_type::min() : t;
  };
  auto inputs = fs::file_time_type::min();
  for (const char* name : kSharedInputs) inputs = std::max(inputs, mtime(name));
  bool changed = false;
  for (FrameEntry& f : m_manifest.frames) {
    if (f.input_hash.empty()) continue;
    for (PictureRecord* p : {&f.image, f.mask ? &*f.mask : nullptr}) {
      // Rendered from the current inputs: nothing to adopt. A picture rendered before an edit
      // (notice_hand_edits) is adopted if POV-Ray made it again since.
      if (p == nullptr ||
          (p->status == FrameStatus::rendered && p->rendered_hash == f.input_hash)) {
        continue;
      }
      std::error_code error;
      const auto written = fs::last_write_time(m_dir / p->path, error);
      if (error) continue;
      auto newest_input = inputs;
      for (const std::string& own : frame_inputs(f))
        newest_input = std::max(newest_input, mtime(own));
      if (written <= newest_input) continue;  // older than what it should show
      const auto& id = m_manifest.identity;
      const auto facts = file_facts(m_dir / p->path);
      if (!facts || !image_is_complete(m_dir / p->path, id.width, id.height)) continue;
      p->status = FrameStatus::rendered;
      p->rendered_hash = f.input_hash;
      p->size = facts->size;
      p->file_hash = facts->hash;
      p->seconds = 0.0;
      p->error.clear();
      changed = true;
    }
  }
  if (changed) save();
}

int FolderState::digits() const { return frame_digits(m_manifest); }

const FrameEntry* FolderState::find(int number) const {
  const auto it = std::lower_bound(m_manifest.frames.begin(), m_manifest.frames.end(), number,
                                   [](const FrameEntry& f, int n) { return f.number < n; });
  return it != m_manifest.frames.end() && it->number == number ? &*it : nullptr;
}

FrameEntry* FolderState::find_mutable(int number) {
  return const_cast<FrameEntry*>(std::as_const(*this).find(number));
}

PictureRecord* FolderState::picture(Pass pass, int number) {
  FrameEntry* f = find_mutable(number);
  if (f == nullptr) return nullptr;
  if (pass == Pass::image) return &f->image;
  return f->mask ? &*f->mask : nullptr;
}

void FolderState::begin_export(const std::string& shared_hash, FrameSpan range, int frame_count) {
  auto& frames = m_manifest.frames;
  // A shorter scene: the frames it no longer has go, with the files recorded for them.
  const auto beyond = std::find_if(frames.begin(), frames.end(),
                                   [&](const FrameEntry& f) { return f.number > frame_count; });
  for (auto it = beyond; it != frames.end(); ++it) remove_frame_files(m_dir, *it);
  frames.erase(beyond, frames.end());
  // The records of files no frame left reads alone; the shared files' stay.
  std::erase_if(m_manifest.input_files, [&](const InputFileRecord& r) {
    const bool shared = std::find(std::begin(kSharedInputs), std::end(kSharedInputs), r.path) !=
                        std::end(kSharedInputs);
    return !shared && std::none_of(frames.begin(), frames.end(),
                                   [&](const FrameEntry& f) { return reads(f, r.path); });
  });
  record_inputs({std::begin(kSharedInputs), std::end(kSharedInputs)});
  const bool shared_changed =
      !m_manifest.shared_hash.empty() && m_manifest.shared_hash != shared_hash;
  m_manifest.raintrace_version = RAINTRACE_VERSION;
  m_manifest.shared_hash = shared_hash;
  m_manifest.frame_count = frame_count;
  const int digits = povgen::frame_digits(frame_count);
  for (FrameEntry& f : frames) {
    if (range.contains(f.number) || shared_changed) f.input_hash.clear();
  }
  for (int n = range.first; n <= range.last; ++n) {
    if (find(n) != nullptr) continue;
    FrameEntry f;
    f.number = n;
    f.image = new_picture(Pass::image, n, digits);
    f.developed.path = developed_image_name(n, digits);
    if (m_manifest.identity.masks) f.mask = new_picture(Pass::mask, n, digits);
    frames.push_back(std::move(f));
  }
  std::sort(frames.begin(), frames.end(),
            [](const auto& a, const auto& b) { return a.number < b.number; });
  save();
}

void FolderState::frame_exported(int number, const std::string& input_hash) {
  FrameEntry* f = find_mutable(number);
  if (f == nullptr) return;  // not in this export's range: nothing vouches for it
  f->input_hash = input_hash;
  record_inputs(frame_inputs(*f));  // a frame without a ripple map records none
  for (PictureRecord* p : {&f->image, f->mask ? &*f->mask : nullptr}) {
    if (p != nullptr && p->status == FrameStatus::rendered && p->rendered_hash != input_hash) {
      p->status = FrameStatus::exported;  // rendered_hash stays: "inputs changed"
    }
  }
}

void FolderState::rendering(Pass pass, FrameSpan span) {
  for (int n = span.first; n <= span.last; ++n) {
    if (PictureRecord* p = picture(pass, n)) p->status = FrameStatus::rendering;
  }
}

void FolderState::rendered(Pass pass, int number, double seconds) {
  PictureRecord* p = picture(pass, number);
  if (p == nullptr) return;
  const auto facts = file_facts(m_dir / p->path);
  if (!facts) {
    p->status = FrameStatus::failed;
    p->error = p->path + " vanished after it was rendered";
  } else {
    p->status = FrameStatus::rendered;
    p->rendered_hash = find(number)->input_hash;
    p->size = facts->size;
    p->file_hash = facts->hash;
    p->seconds = seconds;
    p->error.clear();
    DevelopRecord& d = find_mutable(number)->developed;
    if (pass == Pass::image && d.source_hash != facts->hash) {
      d = fresh_develop_record(d.path);  // a PNG of another EXR is no PNG of this one
    }
  }
  save();
}

void FolderState::failed(Pass pass, int number, const std::string& error) {
  PictureRecord* p = picture(pass, number);
  if (p == nullptr) return;
  p->status = FrameStatus::failed;
  p->rendered_hash.clear();
  p->size = 0;
  p->file_hash.clear();
  p->error = error;
  save();
}

void FolderState::set_develop(const DevelopSpec& spec) {
  m_manifest.develop = spec;
  save();
}

void FolderState::set_develop_hash(std::string hash) { m_develop_hash = std::move(hash); }

void FolderState::developed(int number, double seconds) {
  FrameEntry* f = find_mutable(number);
  if (f == nullptr) return;
  DevelopRecord& d = f->developed;
  const auto facts = file_facts(m_dir / d.path);
  if (!facts) {
    develop_failed(number, d.path + " vanished after it was developed");
    return;
  }
  d.develop_hash = m_develop_hash;
  d.source_hash = f->image.file_hash;
  d.size = facts->size;
  d.file_hash = facts->hash;
  d.seconds = seconds;
  d.error.clear();
  save();
}

void FolderState::develop_failed(int number, const std::string& error) {
  FrameEntry* f = find_mutable(number);
  if (f == nullptr) return;
  f->developed = fresh_develop_record(f->developed.path);
  f->developed.error = error;
  save();
}

DevelopReason FolderState::decide_develop(int number) const {
  return decide_develop(number, decide(Pass::image, number, false));
}

DevelopReason FolderState::decide_develop(int number, RenderReason image) const {
  const FrameEntry* f = find(number);
  if (f == nullptr || image != RenderReason::up_to_date) return DevelopReason::not_rendered;
  const DevelopRecord& d = f->developed;
  if (d.develop_hash.empty()) {
    return d.error.empty() ? DevelopReason::new_frame : DevelopReason::failed_before;
  }
  if (d.source_hash != f->image.file_hash) return DevelopReason::new_frame;
  if (d.develop_hash != m_develop_hash) return DevelopReason::settings_changed;
  const auto facts = file_facts(m_dir / d.path);
  if (!facts) return DevelopReason::file_missing;
  if (facts->size != d.size || facts->hash != d.file_hash) return DevelopReason::file_changed;
  return DevelopReason::up_to_date;
}

RenderReason FolderState::decide(Pass pass, int number, bool force) const {
  const FrameEntry* f = find(number);
  if (f == nullptr || f->input_hash.empty()) return RenderReason::not_exported;
  const PictureRecord* p = pass == Pass::image ? &f->image : (f->mask ? &*f->mask : nullptr);
  if (p == nullptr) return RenderReason::not_exported;
  if (force) return RenderReason::forced;
  switch (p->status) {
    case FrameStatus::exported:
      return p->rendered_hash.empty() ? RenderReason::new_frame : RenderReason::inputs_changed;
    case FrameStatus::rendering:
      return RenderReason::interrupted;
    case FrameStatus::failed:
      return RenderReason::failed_before;
    case FrameStatus::rendered:
      break;
  }
  if (p->rendered_hash != f->input_hash) return RenderReason::inputs_changed;
  const auto facts = file_facts(m_dir / p->path);
  if (!facts) return RenderReason::file_missing;
  if (facts->size == p->size && facts->hash == p->file_hash) return RenderReason::up_to_date;
  if (facts->size == 0) return RenderReason::file_empty;
  const auto& id = m_manifest.identity;
  if (facts->size < p->size && !image_is_complete(m_dir / p->path, id.width, id.height)) {
    return RenderReason::file_truncated;
  }
  return RenderReason::file_changed;
}

RenderPlan FolderState::plan(const RenderRequest& request) const {
  RenderPlan plan;
  for (const FrameEntry& f : m_manifest.frames) {
    if (request.only && !request.only->contains(f.number)) continue;
    ++plan.frames;
    const RenderReason image = decide(Pass::image, f.number, request.force);
    ++plan.reasons[image];
    if (needs_render(image)) plan.images.push_back(f.number);
    const DevelopReason develop = decide_develop(f.number, image);
    const bool develop_only = needs_develop(develop);
    if (develop_only) {
      plan.develops.push_back(f.number);
      ++plan.develop_reasons[develop];
    }
    bool mask_to_render = false;
    if (f.mask) {
      const RenderReason mask = decide(Pass::mask, f.number, request.force);
      ++plan.reasons[mask];
      mask_to_render = needs_render(mask);
      if (mask_to_render) plan.masks.push_back(f.number);
    }
    if (image == RenderReason::up_to_date && !develop_only && !mask_to_render) ++plan.up_to_date;
  }
  return plan;
}

std::vector<int> FolderState::verified_frames() const {
  std::vector<int> frames;
  for (const FrameEntry& f : m_manifest.frames) {
    if (decide_develop(f.number) == DevelopReason::up_to_date) frames.push_back(f.number);
  }
  return frames;
}

void FolderState::save() const { write_manifest(m_dir / kManifest, m_manifest); }

void FolderState::set_movie_source(const std::string& key) {
  m_manifest.movie_source = key;
  save();
}

void FolderState::set_contact_sheet_source(const std::string& key) {
  m_manifest.contact_sheet_source = key;
  save();
}

std::string develop_hash(const DevelopSpec& spec, std::uint64_t seed,
                         const film::RgbImage& response) {
  povgen::ContentHasher hasher;
  // The opening matters only to the spikes: named only with them, so other folders' hashes stay.
  const std::string aperture =
      spec.settings.aperture_blades != 0 ? fmt::format(" aperture_m={}", spec.aperture_m) : "";
  hasher.update(fmt::format("{} fov_deg={}{} seed={}\n", film::describe(spec.settings),
                            spec.fov_deg, aperture, seed));
  hasher.update(std::string_view{reinterpret_cast<const char*>(response.pixels.data()),
                                 response.pixels.size() * sizeof(float)});
  return hasher.hex();
}

std::string assembly_key(const FolderState& folder, const std::vector<int>& frames) {
  povgen::ContentHasher hasher;
  for (const int n : frames) {
    const FrameEntry* f = folder.find(n);
    hasher.update(fmt::format("{}:{};", n, f != nullptr ? f->developed.file_hash : ""));
  }
  return hasher.hex();
}

}  // namespace raintrace::output
