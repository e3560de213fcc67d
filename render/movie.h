// The finished frames as an MP4 (H.264, yuv420p, even size: plays everywhere) and an animated
// GIF (two-pass palette so rain streaks do not dither into noise), both made by ffmpeg.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace raintrace::render {

/// Which images a movie shows: images/frame_NNNN.png for first_frame .. first_frame + count − 1
/// (ffmpeg stops there even when later images exist: they may not belong to the movie).
struct MovieFrames {
  int first = 1;
  int count = 1;
  int digits = 4;
};

/// ffmpeg argv for the MP4 of `frames`, written to output.
std::vector<std::string> mp4_argv(double fps, const MovieFrames& frames, const std::string& output);
/// ffmpeg argv for the GIF (palettegen + paletteuse in one filter graph).
std::vector<std::string> gif_argv(double fps, const MovieFrames& frames, const std::string& output);

struct MovieResult {
  std::filesystem::path mp4;  ///< empty when not made
  std::filesystem::path gif;
  std::string warning;  ///< why something was not made (ffmpeg missing or failed)
};

/// Makes out_dir/animation.mp4 and out_dir/animation.gif from the frames, each through a temp
/// name renamed on success; a movie that could not be made is removed (an older one would show
/// other frames). A missing or failing ffmpeg is a warning, the frames are the result that
/// matters; a full disk throws std::system_error (ENOSPC).
MovieResult make_movies(const std::filesystem::path& out_dir, double fps,
                        const MovieFrames& frames);

}  // namespace raintrace::render
