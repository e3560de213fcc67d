// Exit codes shared by every subcommand, so scripts and CI can tell outcomes apart, and the one
// line main() prints for an error.
#pragma once

#include <exception>
#include <string>

namespace raintrace::cli::exit_code {
inline constexpr int ok = 0;
/// Some work finished but part of it failed (frames that did not render, images that differ).
inline constexpr int failed = 1;
/// Nothing useful happened: bad scene file, bad option, unusable input, missing tool, an output
/// folder that holds another scene's files (or another tool's) without --force.
inline constexpr int error = 2;
/// The system refused: disk full, permission denied, I/O error, out of processes. The message
/// names the file and the system's reason.
inline constexpr int system_error = 3;
/// The output folder is in use by another raintrace run (the message says which); try again
/// when it has finished.
inline constexpr int busy = 4;
// 128 + signal number when interrupted: 130 for SIGINT (Ctrl-C), 143 for SIGTERM.
}  // namespace raintrace::cli::exit_code

namespace raintrace::cli {

/// The exit code for an error that ended a command: busy for output::FolderBusy, system_error
/// for std::system_error (std::filesystem::filesystem_error included), else error.
int exit_code_for(const std::exception& e);

/// e.what() for the user: one line, and a message longer than a screen (a value quoted whole
/// from a huge input) cut, saying how much was left out.
std::string error_line(const std::exception& e);

}  // namespace raintrace::cli
