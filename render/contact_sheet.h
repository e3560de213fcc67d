// A contact sheet: a few evenly spaced frames in a grid, each labelled with its frame number,
// for a quick look at a whole animation in one PNG (OpenImageIO, no ffmpeg needed).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace raintrace::render {

/// `count` frame numbers evenly spaced over the ascending list `frames`, always including the
/// first and the last (all of them when there are no more than count).
std::vector<int> pick_evenly(const std::vector<int>& frames, int count);

struct ContactSheetResult {
  std::filesystem::path path;  ///< empty when nothing was made
  std::string note;            ///< e.g. labels skipped because no font was found
};

/// Writes out_dir/contact_sheet.png from up to `count` of the given frames'
/// images/frame_NNNN.png, in a grid of ceil(sqrt(n)) columns with a 4-pixel gap and a label
/// strip under each cell. Throws std::runtime_error when an image cannot be read or written.
ContactSheetResult make_contact_sheet(const std::filesystem::path& out_dir,
                                      const std::vector<int>& frames, int count = 9,
                                      int digits = 4);

}  // namespace raintrace::render
