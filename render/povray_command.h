// How raintrace calls POV-Ray on an exported folder: the command line for one range of frames
// (pure, so tests can check it without POV-Ray) and the folder conventions it relies on.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "output/layout.h"

namespace raintrace::render {

// A contiguous run of frames (one POV-Ray process renders one), the scene variant it renders
// and the final image names: the output folder's layout (output/layout.h).
using output::developed_image_name;
using output::final_image_name;
using output::FrameSpan;
using output::Pass;

/// Where POV-Ray writes a picture first ("images/.tmp/frame_0007.exr", "images/.tmp/
/// mask_0007.png"); renamed to its final_image_name only once verified.
std::string temp_image_name(Pass pass, int frame, int digits = 4);
/// Where develop writes a frame's PNG first ("images/.tmp/frame_0007.png"); renamed to its
/// developed_image_name only once verified.
std::string temp_developed_name(int frame, int digits = 4);
/// The folder of temp_image_name, relative to the output folder.
std::string temp_dir_name();

/// argv for `povray` rendering `span` of the folder's animation. Runs with the output folder as
/// working directory (relative includes resolve there, +L. adds it to the library path):
///   povray scene.ini -D +FE +V +RS7 -GR +L. +Oimages/.tmp/frame_.exr +KFI1 +KFF9999 +SFa +EFb
///   povray mask.ini -D +FN +V +RS7 -GR +L. +Oimages/.tmp/mask_.png …
/// +FE: half-float OpenEXR, scene-linear (as scene.ini says); masks stay PNG (data, not light).
/// -D: headless; -GR: quiet but keeps POV-Ray's "File '…' line N:" error lines
/// (docs/povray-notes.md); +V: its "Rendered N of M pixels" after each 32×32 block, which the
/// ETA reads (povray_traced_share); +RS7: the blocks traced seven apart, round and round the
/// frame, so the share of pixels traced is the share of the frame's time (the same pixels; in
/// POV-Ray's own order the fast sky at the top made half the pixels take 29 % of the time).
/// +KFI1 +KFF9999 (as many nines as `digits`) keep frame_number and the zero-padded names
/// identical to the ini's whole animation.
std::vector<std::string> povray_argv(Pass pass, const FrameSpan& span, int digits = 4);

/// Where POV-Ray writes the environment plate first ("images/.tmp/environment_plate.exr").
std::string environment_plate_temp_name();

/// argv for `povray` rendering the folder's environment plate (plate.ini, one still image) into
/// environment_plate_temp_name(), with the output folder as working directory like
/// povray_argv:
///   povray plate.ini -D +FE -V -GR +L. +Oimages/.tmp/environment_plate.exr
std::vector<std::string> environment_plate_argv();

/// Environment for POV-Ray: HOME = out_dir, where prepare_povray_home() put an empty
/// .povray/3.7/povray.conf (silences the harmless "cannot open user configuration" warning).
std::map<std::string, std::string> povray_env(const std::filesystem::path& out_dir);
void prepare_povray_home(const std::filesystem::path& out_dir);

/// The lines of a POV-Ray log that explain a failure: each "File '…' line N: …" message joined
/// with its wrapped continuation lines, then any other error lines ("Fatal error…",
/// "Render failed", "Parse Error…"), and a missing font with the Debian package that ships
/// POV-Ray's fonts. Empty when the log names no error.
std::vector<std::string> povray_error_lines(const std::string& log_text);

/// What POV-Ray prints when it gives up before reading anything: its front end waits 3 s for its
/// own worker thread to start (vfeInitializeTimedOut in its vfe/vfesession.cpp), and a loaded
/// machine can miss that. Nothing was parsed or traced, so the same command may run again.
inline constexpr const char* kPovrayStartupTimeout = "Timed out waiting for worker thread startup";

/// How much of the frame it is tracing a POV-Ray log (or the log's tail) says is traced: the last
/// "Rendered N of M pixels" (+V prints one after each block, separated by carriage returns), as
/// N / M; nullopt when there is none. 1 once a frame is whole, until the next frame's first block.
std::optional<double> povray_traced_share(std::string_view log_text);

/// True when the log says POV-Ray did not start (kPovrayStartupTimeout).
bool povray_did_not_start(const std::string& log_text);

/// The line a failure report gives for work POV-Ray never started on, after `starts` starts.
std::string povray_did_not_start_line(int starts);

/// POV-Ray is started this many times in all on the same work (a span of frames, or the
/// environment plate) whose process ended because it did not start, before that work counts as
/// failed.
inline constexpr int kPovrayStartAttempts = 4;

}  // namespace raintrace::render
