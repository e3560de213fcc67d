// ffmpeg invocations. Frames are numbered images/frame_NNNN.png; -start_number lets a run that
// rendered only --frames A-B still make a movie of what exists from A on.
#include "render/movie.h"

#include <fmt/core.h>

#include "output/disk_space.h"
#include "output/layout.h"
#include "render/process.h"

namespace raintrace::render {
namespace {

std::vector<std::string> input_args(double fps, const MovieFrames& frames) {
  return {"ffmpeg",
          "-hide_banner",
          "-loglevel",
          "error",
          "-y",
          "-framerate",
          fmt::format("{}", fps),
          "-start_number",
          std::to_string(frames.first),
          "-i",
          fmt::format("images/frame_%0{}d.png", frames.digits),
          "-frames:v",
          std::to_string(frames.count)};
}

}  // namespace

std::vector<std::string> mp4_argv(double fps, const MovieFrames& frames,
                                  const std::string& output) {
  auto argv = input_args(fps, frames);
  // libx264 with yuv420p needs even width and height: round down by at most one pixel.
  argv.insert(argv.end(),
              {"-vf", "scale=trunc(iw/2)*2:trunc(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p",
               "-crf", "18", "-movflags", "+faststart", "-f", "mp4", output});
  return argv;
}

std::vector<std::string> gif_argv(double fps, const MovieFrames& frames,
                                  const std::string& output) {
  auto argv = input_args(fps, frames);
  argv.insert(argv.end(), {"-filter_complex",
                           "split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse=dither="
                           "bayer:bayer_scale=3",
                           "-loop", "0", "-f", "gif", output});
  return argv;
}

MovieResult make_movies(const std::filesystem::path& out_dir, double fps,
                        const MovieFrames& frames) {
  MovieResult result;
  if (!find_program("ffmpeg")) {
    std::filesystem::remove(out_dir / output::kMovie);
    std::filesystem::remove(out_dir / output::kGif);
    result.warning =
        "ffmpeg not found: no MP4/GIF made (install it with `sudo apt-get install ffmpeg`)";
    return result;
  }
  std::filesystem::create_directories(out_dir / "logs");
  auto run = [&](const std::vector<std::string>& argv, const std::string& name,
                 std::filesystem::path& made) {
    ProcessSpec spec;
    spec.argv = argv;
    spec.working_dir = out_dir;
    spec.log_path = out_dir / "logs" / (name + ".ffmpeg.log");
    const int code = ChildProcess{spec}.wait();
    const auto temp = out_dir / (".tmp." + name);
    if (code == 0 && std::filesystem::exists(temp)) {
      std::filesystem::rename(temp, out_dir / name);
      made = out_dir / name;
    } else {
      std::filesystem::remove(temp);
      std::filesystem::remove(out_dir / name);
      output::throw_if_out_of_space(
          out_dir, 1 << 20,
          fmt::format("ffmpeg could not write {} into {}", name, out_dir.string()));
      if (!result.warning.empty()) result.warning += "; ";
      result.warning += fmt::format(
          "ffmpeg failed making {} (exit code {}, see logs/{}.ffmpeg.log)", name, code, name);
    }
  };
  run(mp4_argv(fps, frames, ".tmp.animation.mp4"), output::kMovie, result.mp4);
  run(gif_argv(fps, frames, ".tmp.animation.gif"), output::kGif, result.gif);
  return result;
}

}  // namespace raintrace::render
