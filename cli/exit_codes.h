// Exit codes shared by every subcommand, so scripts and CI can tell outcomes apart.
#pragma once

namespace raintrace::cli::exit_code {
inline constexpr int ok = 0;
/// Some work finished but part of it failed (frames that did not render, images that differ).
inline constexpr int failed = 1;
/// Nothing useful happened: bad scene file, bad option, unusable input, missing tool.
inline constexpr int error = 2;
}  // namespace raintrace::cli::exit_code
