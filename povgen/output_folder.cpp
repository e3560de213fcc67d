// Writing the shared files of an output folder.
#include "povgen/output_folder.h"

#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "povgen/frame_text.h"
#include "povgen/manifest.h"
#include "povgen/scene_files.h"
#include "povgen/streak_atlas.h"
#include "povgen/templates.h"

namespace raintrace::povgen {

void write_file_atomic(const std::filesystem::path& path, std::string_view bytes) {
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
  }
  std::error_code error;
  std::filesystem::rename(tmp, path, error);
  if (error) {
    throw std::runtime_error("cannot rename " + tmp.string() + " to " + path.string() + ": " +
                             error.message());
  }
}

void create_output_folders(const std::filesystem::path& out_dir) {
  for (const char* sub : {"frames", "textures", "images"}) {
    std::error_code error;
    std::filesystem::create_directories(out_dir / sub, error);
    if (error) {
      throw std::runtime_error("cannot create " + (out_dir / sub).string() + ": " +
                               error.message());
    }
  }
}

std::string write_frame_file(const std::filesystem::path& path, const FrameValues& values,
                             std::string_view hash_prefix, int threads) {
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(tmp.c_str(), "wb"), &std::fclose);
  if (!file) throw std::runtime_error("cannot write " + tmp.string());
  ContentHasher hasher;
  hasher.update(hash_prefix);
  bool ok = true;
  write_frame_text(
      values,
      [&](std::string_view piece) {
        hasher.update(piece);
        ok = ok && std::fwrite(piece.data(), 1, piece.size(), file.get()) == piece.size();
      },
      StreakAtlasLayout{}, threads);
  ok = std::fflush(file.get()) == 0 && ok;
  ok = std::fclose(file.release()) == 0 && ok;
  if (!ok) throw std::runtime_error("cannot write " + tmp.string() + " (disk full?)");
  std::error_code error;
  std::filesystem::rename(tmp, path, error);
  if (error) {
    throw std::runtime_error("cannot rename " + tmp.string() + " to " + path.string() + ": " +
                             error.message());
  }
  return hasher.hex();
}

std::string read_file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

std::string write_shared_files(const std::filesystem::path& out_dir, const ExportParams& look,
                               int frame_count, const std::filesystem::path& scene_dir,
                               FrameSubset frames) {
  create_output_folders(out_dir);
  const int digits = frame_digits(frame_count);
  std::string all;  // every shared file's bytes in a fixed order, for the hash
  // Writes `bytes` and hashes `hashed` (the same bytes, except for the .ini files' frame range).
  auto emit = [&](const char* name, const std::string& bytes, const std::string& hashed) {
    write_file_atomic(out_dir / name, bytes);
    all += name;
    all += '\0';
    all += hashed;
  };
  const FrameSubset whole{1, frame_count};
  auto emit_same = [&](const char* name, const std::string& bytes) { emit(name, bytes, bytes); };
  emit_same(kSceneInclude, scene_inc_text(look));
  emit_same("scene.pov", dispatcher_text("frame", digits));
  emit("scene.ini", ini_text(look, frame_count, "frame", "scene.pov", frames),
       ini_text(look, frame_count, "frame", "scene.pov", whole));
  emit_same(kEnvironmentInclude, environment_text(look.environment, scene_dir));
  emit_same(kMaterialsInclude, materials_template());
  if (environment_plate_applies(look)) {
    emit_same(kPlatePov, plate_pov_text());
    emit_same(kPlateIni, plate_ini_text(look));
  } else {
    // Left by an earlier export into this folder: render/ takes plate.ini as asking for a plate.
    std::filesystem::remove(out_dir / kPlatePov);
    std::filesystem::remove(out_dir / kPlateIni);
  }
  if (look.mask) {
    emit_same("mask.pov", dispatcher_text("mask", digits));
    emit("mask.ini", ini_text(look, frame_count, "mask", "mask.pov", frames),
         ini_text(look, frame_count, "mask", "mask.pov", whole));
  }
  // OpenImageIO picks the format from the extension, so the temporary name keeps ".png".
  const std::filesystem::path atlas = out_dir / kStreakAtlas;
  std::filesystem::path tmp = atlas;
  tmp.replace_filename("streak_atlas.tmp.png");
  write_streak_atlas(tmp, StreakAtlasLayout{});
  std::error_code error;
  std::filesystem::rename(tmp, atlas, error);
  if (error) throw std::runtime_error("cannot rename " + tmp.string() + ": " + error.message());
  all += kStreakAtlas;
  all += '\0';
  all += read_file_bytes(atlas);
  return content_hash(all);
}

}  // namespace raintrace::povgen
