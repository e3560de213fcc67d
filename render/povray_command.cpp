// POV-Ray command lines and log reading. Facts behind the flags are in docs/povray-notes.md.
#include "render/povray_command.h"

#include <fmt/core.h>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "povgen/scene_files.h"

namespace raintrace::render {

namespace {
const char* prefix(Pass pass) { return output::pass_prefix(pass); }

// The extension of the pass's picture: EXR for the frame (light), PNG for the mask (data).
const char* extension(Pass pass) { return pass == Pass::image ? "exr" : "png"; }

}  // namespace

std::string temp_dir_name() { return "images/.tmp"; }

std::string temp_image_name(Pass pass, int frame, int digits) {
  return fmt::format("{}/{}_{:0{}d}.{}", temp_dir_name(), prefix(pass), frame, digits,
                     extension(pass));
}

std::string temp_developed_name(int frame, int digits) {
  return fmt::format("{}/{}_{:0{}d}.png", temp_dir_name(), prefix(Pass::image), frame, digits);
}

std::vector<std::string> povray_argv(Pass pass, const FrameSpan& span, int digits) {
  // POV-Ray appends the frame number (padded to Final_Frame's digits) before the extension.
  return {"povray",
          pass == Pass::image ? "scene.ini" : "mask.ini",
          "-D",
          pass == Pass::image ? "+FE" : "+FN",
          "+V",
          "+RS7",
          "-GR",
          "+L.",
          fmt::format("+O{}/{}_.{}", temp_dir_name(), prefix(pass), extension(pass)),
          "+KFI1",
          "+KFF" + std::string(static_cast<std::size_t>(digits), '9'),
          fmt::format("+SF{}", span.first),
          fmt::format("+EF{}", span.last)};
}

std::string environment_plate_temp_name() { return temp_dir_name() + "/environment_plate.exr"; }

std::vector<std::string> environment_plate_argv() {
  // +O overrides plate.ini's Output_File_Name: the plate reaches its final name only verified.
  return {"povray", povgen::kPlateIni,
          "-D",     "+FE",
          "-V",     "-GR",
          "+L.",    "+O" + environment_plate_temp_name()};
}

std::map<std::string, std::string> povray_env(const std::filesystem::path& out_dir) {
  return {{"HOME", std::filesystem::absolute(out_dir).string()}};
}

void prepare_povray_home(const std::filesystem::path& out_dir) {
  const auto dir = out_dir / ".povray" / "3.7";
  std::filesystem::create_directories(dir);
  const auto conf = dir / "povray.conf";
  if (!std::filesystem::exists(conf)) std::ofstream{conf};
}

std::optional<double> povray_traced_share(std::string_view log_text) {
  constexpr std::string_view kRendered = "Rendered ";
  const std::size_t at = log_text.rfind(kRendered);
  if (at == std::string_view::npos) return std::nullopt;
  // "Rendered 1024 of 921600 pixels (0%)"; a tail may cut the last line short.
  long traced = 0;
  long total = 0;
  const std::string line{log_text.substr(at, 64)};
  if (std::sscanf(line.c_str(), "Rendered %ld of %ld pixels", &traced, &total) != 2 || total <= 0 ||
      traced < 0 || traced > total) {
    return std::nullopt;
  }
  return static_cast<double>(traced) / static_cast<double>(total);
}

bool povray_did_not_start(const std::string& log_text) {
  return log_text.find(kPovrayStartupTimeout) != std::string::npos;
}

std::string povray_did_not_start_line(int starts) {
  return fmt::format("POV-Ray did not start, {} times: {}", starts, kPovrayStartupTimeout);
}

std::vector<std::string> povray_error_lines(const std::string& log_text) {
  std::vector<std::string> lines;
  std::istringstream in{log_text};
  std::string line;
  bool in_message = false;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    // +V's progress ("Rendered N of M pixels (P%)\r" after each block) shares a line with
    // whatever POV-Ray prints next: only what follows the last carriage return is a message.
    if (const std::size_t cr = line.rfind('\r'); cr != std::string::npos) line.erase(0, cr + 1);
    // POV-Ray wraps messages at ~80 columns; continuation lines start with one space.
    if (in_message && line.size() > 1 && line[0] == ' ' && line[1] != ' ') {
      lines.back() += line;
      continue;
    }
    in_message = false;
    // A missing font is only a "Possible Parse Error"; the fatal error after it says "Cannot open
    // file." without naming one. Keep it, with the remedy: night_street's signs use a font that
    // ships with POV-Ray's include files, which Debian packages apart from povray.
    if (line.find("Cannot open font file") != std::string::npos) {
      lines.push_back(line +
                      " POV-Ray's fonts are missing: install the Debian package "
                      "povray-includes (scripts/install-deps.sh does).");
      continue;
    }
    // Warnings ("Possible Parse Error: …", "File '…' line N: Parse Warning: …") from frames that
    // rendered fine earlier in the same log are not the failure.
    if (line.find("Possible ") != std::string::npos || line.find("Warning") != std::string::npos) {
      continue;
    }
    if (line.rfind("File '", 0) == 0 && line.find(" line ") != std::string::npos) {
      lines.push_back(line);
      in_message = true;
    } else if (line.find("Parse Error") != std::string::npos ||
               line.find("Fatal error") != std::string::npos ||
               line.rfind("Render failed", 0) == 0 || line.rfind("Error:", 0) == 0) {
      lines.push_back(line);
      in_message = true;
    }
  }
  return lines;
}

}  // namespace raintrace::render
