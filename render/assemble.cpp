// Contact sheet and movies from verified frames, remade only when those frames changed.
#include "render/assemble.h"

#include <fmt/core.h>
#include <stdexcept>

#include "output/layout.h"
#include "render/contact_sheet.h"
#include "render/movie.h"

namespace raintrace::render {
namespace {

bool is_file(const std::filesystem::path& path) {
  std::error_code ignored;
  return std::filesystem::is_regular_file(path, ignored);
}

void remove_outputs(const std::filesystem::path& dir, std::initializer_list<const char*> names) {
  for (const char* name : names) std::filesystem::remove(dir / name);
}

}  // namespace

AssemblyResult assemble(output::FolderState& folder, const AssemblyOptions& options) {
  const auto& dir = folder.dir();
  const auto& manifest = folder.manifest();
  AssemblyResult result;
  result.frames = folder.verified_frames();
  const std::string key = result.frames.empty() ? "" : output::assembly_key(folder, result.frames);

  if (result.frames.empty()) {
    remove_outputs(dir, {output::kContactSheet});
    if (!manifest.contact_sheet_source.empty()) folder.set_contact_sheet_source("");
  } else if (key == manifest.contact_sheet_source && is_file(dir / output::kContactSheet)) {
    result.contact_sheet = dir / output::kContactSheet;
  } else {
    const auto sheet =
        make_contact_sheet(dir, result.frames, options.sheet_frames, folder.digits());
    if (!sheet.note.empty()) result.warnings.push_back(sheet.note);
    result.contact_sheet = sheet.path;
    folder.set_contact_sheet_source(key);
  }

  const bool current = !key.empty() && key == manifest.movie_source;
  const bool consecutive =
      result.frames.size() >= 2 &&
      result.frames.back() - result.frames.front() + 1 == static_cast<int>(result.frames.size());
  if (current && is_file(dir / output::kMovie) && is_file(dir / output::kGif)) {
    result.mp4 = dir / output::kMovie;
    result.gif = dir / output::kGif;
    return result;
  }
  if (!options.movie || !consecutive) {
    // Whatever movie is there shows other frames than the folder now has.
    remove_outputs(dir, {output::kMovie, output::kGif});
    if (!manifest.movie_source.empty()) folder.set_movie_source("");
    if (options.movie && result.frames.size() >= 2) {
      result.warnings.push_back("frames are missing: no MP4/GIF made");
    }
    return result;
  }
  const MovieFrames frames{result.frames.front(), static_cast<int>(result.frames.size()),
                           folder.digits()};
  const auto movies =
      make_movies(dir, manifest.identity.fps > 0 ? manifest.identity.fps : 24.0, frames);
  if (!movies.warning.empty()) result.warnings.push_back(movies.warning);
  result.mp4 = movies.mp4;
  result.gif = movies.gif;
  folder.set_movie_source(movies.mp4.empty() && movies.gif.empty() ? "" : key);
  return result;
}

}  // namespace raintrace::render
