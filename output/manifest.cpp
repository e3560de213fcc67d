// manifest.json reading and writing; nlohmann::json stays in this file.
#include "output/manifest.h"

#include <fmt/core.h>
#include <algorithm>
#include <cerrno>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "povgen/frame_text.h"
#include "povgen/output_folder.h"

namespace raintrace::output {
namespace {

using nlohmann::json;

constexpr FrameStatus kStatuses[] = {FrameStatus::exported, FrameStatus::rendering,
                                     FrameStatus::rendered, FrameStatus::failed};

template <typename T>
T field(const json& object, const char* key, const T& fallback) {
  const auto it = object.find(key);
  if (it == object.end() || it->is_null()) return fallback;
  try {
    return it->get<T>();
  } catch (const json::exception& e) {
    throw std::runtime_error(fmt::format("field '{}' has the wrong type: {}", key, e.what()));
  }
}

// A picture's fields sit in the frame object itself for the image (as older manifests had
// them) and in a "mask" object for the mask.
void put_picture(json& object, const PictureRecord& p) {
  object["scene"] = p.scene;
  object["image"] = p.path;
  object["status"] = to_string(p.status);
  object["rendered_hash"] = p.rendered_hash;
  object["image_size"] = p.size;
  object["image_hash"] = p.file_hash;
  object["render_seconds"] = p.seconds;
  object["error"] = p.error;
}

PictureRecord get_picture(const json& object) {
  PictureRecord p;
  p.scene = field<std::string>(object, "scene", "");
  p.path = field<std::string>(object, "image", "");
  const auto status = field<std::string>(object, "status", "exported");
  const auto parsed = parse_frame_status(status);
  if (!parsed) throw std::runtime_error(fmt::format("unknown status '{}'", status.substr(0, 40)));
  p.status = *parsed;
  p.rendered_hash = field<std::string>(object, "rendered_hash", "");
  p.size = field<std::uint64_t>(object, "image_size", 0);
  p.file_hash = field<std::string>(object, "image_hash", "");
  p.seconds = field<double>(object, "render_seconds", 0.0);
  p.error = field<std::string>(object, "error", "");
  return p;
}

json develop_record_to_json(const DevelopRecord& d) {
  return {{"image", d.path},      {"develop_hash", d.develop_hash}, {"source_hash", d.source_hash},
          {"image_size", d.size}, {"image_hash", d.file_hash},      {"develop_seconds", d.seconds},
          {"error", d.error}};
}

DevelopRecord develop_record_from_json(const json& object) {
  if (!object.is_object()) throw std::runtime_error("'developed' must be an object");
  DevelopRecord d;
  d.path = field<std::string>(object, "image", "");
  d.develop_hash = field<std::string>(object, "develop_hash", "");
  d.source_hash = field<std::string>(object, "source_hash", "");
  d.size = field<std::uint64_t>(object, "image_size", 0);
  d.file_hash = field<std::string>(object, "image_hash", "");
  d.seconds = field<double>(object, "develop_seconds", 0.0);
  d.error = field<std::string>(object, "error", "");
  return d;
}

json develop_spec_to_json(const DevelopSpec& spec) {
  const film::DevelopSettings& s = spec.settings;
  return {{"exposure_ev", s.exposure_ev},
          {"white_balance_k", s.white_balance_k},
          {"view", std::string{film::to_string(s.view)}},
          {"look", std::string{film::to_string(s.look)}},
          {"bloom", s.bloom},
          {"softness", s.softness},
          {"grain", s.grain},
          {"sensor_noise", s.sensor_noise},
          {"vignette", s.vignette},
          {"aperture_blades", s.aperture_blades},
          {"fov_deg", spec.fov_deg},
          {"aperture_m", spec.aperture_m}};
}

DevelopSpec develop_spec_from_json(const json& object) {
  if (!object.is_object()) throw std::runtime_error("'develop' must be an object");
  DevelopSpec spec;
  film::DevelopSettings& s = spec.settings;
  s.exposure_ev = field<double>(object, "exposure_ev", s.exposure_ev);
  const auto view = field<std::string>(object, "view", std::string{film::to_string(s.view)});
  const auto look = field<std::string>(object, "look", std::string{film::to_string(s.look)});
  const auto parsed_view = film::parse_view(view);
  const auto parsed_look = film::parse_look(look);
  if (!parsed_view) throw std::runtime_error(fmt::format("unknown view '{}'", view.substr(0, 40)));
  if (!parsed_look) throw std::runtime_error(fmt::format("unknown look '{}'", look.substr(0, 40)));
  s.view = *parsed_view;
  s.look = *parsed_look;
  s.bloom = field<double>(object, "bloom", s.bloom);
  s.white_balance_k = field<double>(object, "white_balance_k", s.white_balance_k);
  s.softness = field<double>(object, "softness", s.softness);
  s.grain = field<double>(object, "grain", s.grain);
  s.sensor_noise = field<double>(object, "sensor_noise", s.sensor_noise);
  s.vignette = field<double>(object, "vignette", s.vignette);
  s.aperture_blades = field<int>(object, "aperture_blades", s.aperture_blades);
  spec.fov_deg = field<double>(object, "fov_deg", spec.fov_deg);
  spec.aperture_m = field<double>(object, "aperture_m", spec.aperture_m);
  try {
    film::validate(s);
    if (s.aperture_blades != 0 && !(spec.aperture_m > 0.0)) {
      throw std::invalid_argument("aperture_blades needs aperture_m > 0");
    }
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(fmt::format("develop: {}", e.what()));
  }
  return spec;
}

json frame_to_json(const FrameEntry& f) {
  json object{{"number", f.number}, {"input_hash", f.input_hash}};
  put_picture(object, f.image);
  object["developed"] = develop_record_to_json(f.developed);
  if (f.mask) {
    json mask = json::object();
    put_picture(mask, *f.mask);
    object["mask"] = mask;
  }
  return object;
}

FrameEntry frame_from_json(const json& object) {
  if (!object.is_object()) throw std::runtime_error("each frame must be an object");
  FrameEntry f;
  f.number = field<int>(object, "number", 0);
  try {
    f.input_hash = field<std::string>(object, "input_hash", "");
    f.image = get_picture(object);
    const auto developed = object.find("developed");
    if (developed != object.end() && !developed->is_null()) {
      f.developed = develop_record_from_json(*developed);
    }
    const auto mask = object.find("mask");
    if (mask != object.end() && !mask->is_null()) {
      if (!mask->is_object()) throw std::runtime_error("'mask' must be an object");
      f.mask = get_picture(*mask);
    }
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(fmt::format("frame {}: {}", f.number, e.what()));
  }
  return f;
}

}  // namespace

int frame_digits(const Manifest& m) {
  if (!m.frames.empty()) {
    // The digits before the extension of the first image's name.
    const std::string& image = m.frames.front().image.path;
    const auto end = image.rfind('.');
    if (end != std::string::npos && end > 0) {
      const auto start = image.find_last_not_of("0123456789", end - 1);
      if (start != std::string::npos && end - start > 1) return static_cast<int>(end - start - 1);
    }
  }
  return povgen::frame_digits(std::max(1, m.frame_count));
}

const char* to_string(FrameStatus status) {
  switch (status) {
    case FrameStatus::exported:
      return "exported";
    case FrameStatus::rendering:
      return "rendering";
    case FrameStatus::rendered:
      return "rendered";
    case FrameStatus::failed:
      return "failed";
  }
  return "?";
}

std::optional<FrameStatus> parse_frame_status(std::string_view text) {
  for (const FrameStatus s : kStatuses) {
    if (text == to_string(s)) return s;
  }
  return std::nullopt;
}

std::string to_json(const Manifest& m) {
  json frames = json::array();
  for (const FrameEntry& f : m.frames) frames.push_back(frame_to_json(f));
  json inputs = json::array();
  for (const InputFileRecord& r : m.input_files) {
    inputs.push_back({{"path", r.path},
                      {"size", r.size},
                      {"mtime_ns", r.mtime_ns},
                      {"hash", r.hash},
                      {"edited_by_hand", r.by_hand}});
  }
  const FolderIdentity& id = m.identity;
  const json doc{{"raintrace_version", m.raintrace_version},
                 {"folder_format", m.format},
                 {"scene_hash", id.scene_hash},
                 {"seed", id.seed},
                 {"width", id.width},
                 {"height", id.height},
                 {"fps", id.fps},
                 {"quality", std::string(povgen::quality_name(id.quality))},
                 {"masks", id.masks},
                 {"develop", develop_spec_to_json(m.develop)},
                 {"shared_hash", m.shared_hash},
                 {"frame_count", m.frame_count},
                 {"movie_source", m.movie_source},
                 {"contact_sheet_source", m.contact_sheet_source},
                 {"frames", frames},
                 {"input_files", inputs}};
  return doc.dump(2) + "\n";
}

Manifest manifest_from_json(const std::string& text) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    throw std::runtime_error(std::string{"not valid JSON: "} + e.what());
  }
  if (!doc.is_object()) throw std::runtime_error("top level must be an object");
  // The mark of a folder raintrace made: another tool's manifest.json is not ours to change.
  if (!doc.contains("raintrace_version")) {
    throw std::runtime_error("no 'raintrace_version': not written by raintrace");
  }
  Manifest m;
  m.raintrace_version = field<std::string>(doc, "raintrace_version", "");
  m.format = field<int>(doc, "folder_format", 1);
  FolderIdentity& id = m.identity;
  id.scene_hash = field<std::string>(doc, "scene_hash", "");
  id.seed = field<std::uint64_t>(doc, "seed", 0);
  id.width = field<int>(doc, "width", 0);
  id.height = field<int>(doc, "height", 0);
  id.fps = field<double>(doc, "fps", 0.0);
  const auto quality = field<std::string>(doc, "quality", "preview");
  if (quality != "preview" && quality != "final") {
    throw std::runtime_error(fmt::format("unknown quality '{}'", quality.substr(0, 40)));
  }
  id.quality = quality == "final" ? povgen::Quality::final : povgen::Quality::preview;
  id.masks = field<bool>(doc, "masks", false);
  const auto develop = doc.find("develop");
  if (develop != doc.end() && !develop->is_null()) m.develop = develop_spec_from_json(*develop);
  m.shared_hash = field<std::string>(doc, "shared_hash", "");
  m.frame_count = field<int>(doc, "frame_count", 0);
  m.movie_source = field<std::string>(doc, "movie_source", "");
  m.contact_sheet_source = field<std::string>(doc, "contact_sheet_source", "");
  const auto frames = doc.find("frames");
  if (frames != doc.end()) {
    if (!frames->is_array()) throw std::runtime_error("'frames' must be an array");
    for (const json& f : *frames) m.frames.push_back(frame_from_json(f));
  }
  const auto inputs = doc.find("input_files");
  if (inputs != doc.end() && !inputs->is_null()) {
    if (!inputs->is_array()) throw std::runtime_error("'input_files' must be an array");
    for (const json& r : *inputs) {
      if (!r.is_object()) throw std::runtime_error("each input file must be an object");
      m.input_files.push_back(
          {field<std::string>(r, "path", ""), field<std::uint64_t>(r, "size", 0),
           field<std::int64_t>(r, "mtime_ns", 0), field<std::string>(r, "hash", ""),
           field<bool>(r, "edited_by_hand", false)});
    }
  }
  return m;
}

Manifest read_manifest(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw std::system_error(errno, std::generic_category(), "cannot read " + path.string());
  }
  std::ostringstream text;
  text << in.rdbuf();
  try {
    return manifest_from_json(text.str());
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}

void write_manifest(const std::filesystem::path& path, const Manifest& manifest) {
  povgen::write_file_atomic(path, to_json(manifest));
}

}  // namespace raintrace::output
