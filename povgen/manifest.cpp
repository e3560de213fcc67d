// manifest.json reading and writing (nlohmann::json stays in this file) and the FNV-1a hash.
#include "povgen/manifest.h"

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace raintrace::povgen {
namespace {

using nlohmann::json;

json frame_to_json(const FrameEntry& f) {
  return json{{"number", f.number},
              {"scene", f.scene},
              {"image", f.image},
              {"input_hash", f.input_hash},
              {"status", f.status},
              {"rendered_hash", f.rendered_hash},
              {"render_seconds", f.render_seconds},
              {"error", f.error}};
}

template <typename T>
T field(const json& object, const char* key, const T& fallback) {
  const auto it = object.find(key);
  if (it == object.end() || it->is_null()) return fallback;
  try {
    return it->get<T>();
  } catch (const json::exception& e) {
    throw std::runtime_error(std::string{"manifest: field '"} + key +
                             "' has the wrong type: " + e.what());
  }
}

}  // namespace

std::string to_json(const Manifest& manifest) {
  json frames = json::array();
  for (const FrameEntry& f : manifest.frames) frames.push_back(frame_to_json(f));
  const json doc{{"raintrace_version", manifest.raintrace_version},
                 {"scene_hash", manifest.scene_hash},
                 {"seed", manifest.seed},
                 {"width", manifest.width},
                 {"height", manifest.height},
                 {"fps", manifest.fps},
                 {"quality", manifest.quality},
                 {"frames", frames}};
  return doc.dump(2) + "\n";
}

Manifest manifest_from_json(const std::string& text) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    throw std::runtime_error(std::string{"manifest: not valid JSON: "} + e.what());
  }
  if (!doc.is_object()) throw std::runtime_error("manifest: top level must be an object");
  Manifest m;
  m.raintrace_version = field<std::string>(doc, "raintrace_version", "");
  m.scene_hash = field<std::string>(doc, "scene_hash", "");
  m.seed = field<std::uint64_t>(doc, "seed", 0);
  m.width = field<int>(doc, "width", 0);
  m.height = field<int>(doc, "height", 0);
  m.fps = field<double>(doc, "fps", 0.0);
  m.quality = field<std::string>(doc, "quality", "");
  const auto frames = doc.find("frames");
  if (frames != doc.end()) {
    if (!frames->is_array()) throw std::runtime_error("manifest: 'frames' must be an array");
    for (const json& f : *frames) {
      if (!f.is_object()) throw std::runtime_error("manifest: each frame must be an object");
      FrameEntry e;
      e.number = field<int>(f, "number", 0);
      e.scene = field<std::string>(f, "scene", "");
      e.image = field<std::string>(f, "image", "");
      e.input_hash = field<std::string>(f, "input_hash", "");
      e.status = field<std::string>(f, "status", "exported");
      e.rendered_hash = field<std::string>(f, "rendered_hash", "");
      e.render_seconds = field<double>(f, "render_seconds", 0.0);
      e.error = field<std::string>(f, "error", "");
      m.frames.push_back(std::move(e));
    }
  }
  return m;
}

Manifest read_manifest(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read manifest " + path.string());
  std::ostringstream text;
  text << in.rdbuf();
  try {
    return manifest_from_json(text.str());
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}

void write_manifest(const std::filesystem::path& path, const Manifest& manifest) {
  const std::string text = to_json(manifest);
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) throw std::runtime_error("cannot write manifest " + tmp.string());
  }
  std::error_code error;
  std::filesystem::rename(tmp, path, error);
  if (error) {
    throw std::runtime_error("cannot rename " + tmp.string() + " to " + path.string() + ": " +
                             error.message());
  }
}

void ContentHasher::update(std::string_view bytes) {
  std::uint64_t hash = m_hash;
  for (unsigned char c : bytes) {
    hash ^= c;
    hash *= 0x100000001b3ULL;  // FNV-1a 64-bit prime
  }
  m_hash = hash;
}

std::string ContentHasher::hex() const {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(m_hash));
  return text;
}

std::string content_hash(std::string_view bytes) {
  ContentHasher hasher;
  hasher.update(bytes);
  return hasher.hex();
}

}  // namespace raintrace::povgen
