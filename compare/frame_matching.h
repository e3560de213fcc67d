// Pairs the frames of two folders by file name, so a missing or extra frame is reported
// instead of silently shifting every comparison after it.
#pragma once

#include <string>
#include <vector>

namespace raintrace::compare {

struct FramePair {
  std::string name;   ///< the file name, the same on both sides
  bool in_a = false;  ///< present in the reference folder
  bool in_b = false;  ///< present in the candidate folder
};

/// The union of two lists of file names, sorted by name (byte order, so the report order never
/// depends on the file system or locale), each flagged with the sides it appears on. Duplicate
/// names within one list appear once.
std::vector<FramePair> match_frames(std::vector<std::string> a, std::vector<std::string> b);

}  // namespace raintrace::compare
