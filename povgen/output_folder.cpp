// Writing the shared files of an output folder.
#include "povgen/output_folder.h"

#include <fcntl.h>
#include <unistd.h>
#include <cerrno>
#include <cstdio>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "povgen/content_hash.h"
#include "povgen/frame_text.h"
#include "povgen/ground_scene.h"
#include "povgen/scene_files.h"
#include "povgen/streak_atlas.h"
#include "povgen/templates.h"

namespace raintrace::povgen {

namespace {

// Errors carry the system's reason (std::system_error: "… : No space left on device"), so the
// user learns why, and cli/ can tell a full disk from a bad scene.
[[noreturn]] void throw_system_error(int error, const std::string& what) {
  throw std::system_error(error, std::generic_category(), what);
}

void rename_or_throw(const std::filesystem::path& from, const std::filesystem::path& to) {
  std::error_code error;
  std::filesystem::rename(from, to, error);
  if (error) {
    std::filesystem::remove(from, error);
    throw std::system_error(error, "cannot rename " + from.string() + " to " + to.string());
  }
}

/// Writes an image through `write` under a temporary name that keeps the extension (OpenImageIO
/// picks the format by it), then renames it into place. OpenImageIO words its own errors; a
/// full disk or a read-only folder is still in errno and reported as such.
void write_image_atomic(const std::filesystem::path& path,
                        const std::function<void(const std::filesystem::path&)>& write) {
  std::filesystem::path tmp = path;
  tmp.replace_extension(".tmp" + path.extension().string());
  errno = 0;
  try {
    write(tmp);
  } catch (const std::runtime_error&) {
    const int error = errno;
    std::filesystem::remove(tmp);
    if (error == ENOSPC || error == EDQUOT || error == EIO || error == EACCES || error == EROFS) {
      throw_system_error(error, "cannot write " + tmp.string());
    }
    throw;
  }
  rename_or_throw(tmp, path);
}

}  // namespace

void write_file_atomic(const std::filesystem::path& path, std::string_view bytes) {
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw_system_error(errno, "cannot write " + tmp.string());
  std::size_t written = 0;
  int error = 0;
  while (written < bytes.size() && error == 0) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n > 0) {
      written += static_cast<std::size_t>(n);
    } else if (n < 0 && errno != EINTR) {
      error = errno;
    }
  }
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0) {
    ::unlink(tmp.c_str());
    throw_system_error(error, "cannot write " + tmp.string());
  }
  rename_or_throw(tmp, path);
}

void create_output_folders(const std::filesystem::path& out_dir) {
  for (const char* sub : {"frames", "textures", "images"}) {
    std::error_code error;
    std::filesystem::create_directories(out_dir / sub, error);
    if (error) throw std::system_error(error, "cannot create " + (out_dir / sub).string());
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
    if (made) throw_system_error(made.value(), "cannot create " + map.parent_path().string());
    write_image_atomic(
        map, [&](const std::filesystem::path& to) { write_ripple_png(to, values.ripples); });
  }
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(tmp.c_str(), "wbe"),
                                                       &std::fclose);
  if (!file) throw_system_error(errno, "cannot write " + tmp.string());
  ContentHasher hasher;
  hasher.update(hash_prefix);
  int error = 0;  // the first write's errno (ENOSPC on a full disk)
  write_frame_text(
      values,
      [&](std::string_view piece) {
        hasher.update(piece);
        if (error == 0 && std::fwrite(piece.data(), 1, piece.size(), file.get()) != piece.size()) {
          error = errno != 0 ? errno : EIO;
        }
      },
      StreakAtlasLayout{}, threads);
  if (std::fflush(file.get()) != 0 && error == 0) error = errno;
  if (std::fclose(file.release()) != 0 && error == 0) error = errno;
  if (error != 0) {
    ::unlink(tmp.c_str());
    throw_system_error(error, "cannot write " + tmp.string());
  }
  rename_or_throw(tmp, path);
  return hasher.hex();
}

std::string read_file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw_system_error(errno, "cannot read " + path.string());
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
  } else {
    std::filesystem::remove(out_dir / "mask.pov");
    std::filesystem::remove(out_dir / "mask.ini");
  }
  const std::filesystem::path atlas = out_dir / kStreakAtlas;
  write_image_atomic(
      atlas, [](const std::filesystem::path& to) { write_streak_atlas(to, StreakAtlasLayout{}); });
  all += kStreakAtlas;
  all += '\0';
  all += read_file_bytes(atlas);
  if (ground_applies(look)) {
    const std::filesystem::path mask = out_dir / kPuddleMask;
    write_image_atomic(mask, [&](const std::filesystem::path& to) {
      write_mask_png(to, look.width, look.height, ground_puddle_mask(look));
    });
    all += kPuddleMask;
    all += '\0';
    all += read_file_bytes(mask);
  }
  return content_hash(all);
}

}  // namespace raintrace::povgen
