// Writing the shared files of an output folder.
#include "povgen/output_folder.h"

#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "povgen/frame_text.h"
#include "povgen/ground_scene.h"
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
  if (!values.ripples.empty()) {
    // Beside frames/: the frame's text names it and carries its hash (frame_text.h).
    const std::filesystem::path map =
        path.parent_path().parent_path() / ripple_map_name(values.index);
    std::error_code made;
    std::filesystem::create_directories(map.parent_path(), made);
    std::filesystem::path map_tmp = map;
    map_tmp.replace_extension(".tmp.png");
    write_ripple_png(map_tmp, values.ripples);
    std::filesystem::rename(map_tmp, map, made);
    if (made) throw std::runtime_error("cannot rename " + map_tmp.string() + ": " + made.message());
  }
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
                               int frame_count, const std::filesystem::path& scene_dir) {
  create_output_folders(out_dir);
  const int digits = frame_digits(frame_count);
  std::string all;  // every shared file's bytes in a fixed order, for the hash
  auto emit = [&](const char* name, const std::string& bytes) {
    write_file_atomic(out_dir / name, bytes);
    all += name;
    all += '\0';
    all += bytes;
  };
  emit(kSceneInclude, scene_inc_text(look));
  emit("scene.pov", dispatcher_text("frame", digits));
  emit("scene.ini", ini_text(look, frame_count, "frame", "scene.pov"));
  emit(kEnvironmentInclude, environment_text(look.environment, scene_dir));
  emit(kMaterialsInclude, materials_template());
  if (ground_applies(look)) emit(kGroundInclude, ground_template());
  if (environment_plate_applies(look)) {
    emit(kPlatePov, plate_pov_text());
    emit(kPlateIni, plate_ini_text(look));
  } else {
    // Left by an earlier export into this folder: render/ takes plate.ini as asking for a plate.
    std::filesystem::remove(out_dir / kPlatePov);
    std::filesystem::remove(out_dir / kPlateIni);
  }
  if (look.mask) {
    emit("mask.pov", dispatcher_text("mask", digits));
    emit("mask.ini", ini_text(look, frame_count, "mask", "mask.pov"));
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
  if (ground_applies(look)) {
    const std::filesystem::path mask = out_dir / kPuddleMask;
    std::filesystem::path mask_tmp = mask;
    mask_tmp.replace_filename("puddle_mask.tmp.png");
    write_mask_png(mask_tmp, look.width, look.height, ground_puddle_mask(look));
    std::filesystem::rename(mask_tmp, mask, error);
    if (error) {
      throw std::runtime_error("cannot rename " + mask_tmp.string() + ": " + error.message());
    }
    all += kPuddleMask;
    all += '\0';
    all += read_file_bytes(mask);
  }
  return content_hash(all);
}

}  // namespace raintrace::povgen
