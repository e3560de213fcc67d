// Is the output folder's filesystem full? A program that fails to write (POV-Ray, OpenImageIO,
// ffmpeg) often says so in words of its own ("Cannot access data in file") or not at all; asking
// the filesystem afterwards lets raintrace name the real cause and stop, instead of reporting
// every remaining frame as failed.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace raintrace::output {

/// True when the filesystem holding `dir` has less than `needed` bytes free for this process
/// (root may use the blocks reserved for it). False when that cannot be told.
bool out_of_space(const std::filesystem::path& dir, std::uint64_t needed);

/// Throws std::system_error(ENOSPC) with what() "WHAT: No space left on device" when
/// out_of_space(dir, needed); otherwise returns.
void throw_if_out_of_space(const std::filesystem::path& dir, std::uint64_t needed,
                           const std::string& what);

}  // namespace raintrace::output
