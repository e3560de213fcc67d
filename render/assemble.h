// The whole-animation outputs of a folder: contact_sheet.png and animation.mp4/.gif, made only
// from frames whose images are verified now (output::FolderState::verified_frames), and made
// again exactly when those frames changed. An output that can no longer show the current frames
// is removed rather than left behind showing others.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "output/folder_state.h"

namespace raintrace::render {

struct AssemblyOptions {
  bool movie = true;     ///< make the MP4 and GIF (false: keep them only while current)
  int sheet_frames = 9;  ///< frames on the contact sheet
};

struct AssemblyResult {
  std::vector<int> frames;              ///< verified frames, ascending
  std::filesystem::path contact_sheet;  ///< empty when there is none
  std::filesystem::path mp4;            ///< empty when there is none
  std::filesystem::path gif;
  std::vector<std::string> warnings;  ///< one line each: why something was not made
};

/// Brings the contact sheet and the movies up to date with the folder's verified frames and
/// records what they were made from in the manifest. The movies need at least two frames with
/// no gap between them. Throws std::system_error when a file cannot be written.
AssemblyResult assemble(output::FolderState& folder, const AssemblyOptions& options = {});

}  // namespace raintrace::render
