// The HTML report: a self-contained folder (one .html plus the PNGs it shows, relative links,
// no scripts or network) with reference, candidate and difference side by side per frame.
#pragma once

#include <filesystem>
#include <string>

#include "compare/compare_run.h"

namespace raintrace::compare {

/// Where the report's images go: a folder beside the HTML file named "<stem>_files" (as browsers
/// save pages), so moving the two together keeps every link working.
std::filesystem::path html_assets_dir(const std::filesystem::path& html_file);

/// The page for `report`, whose frames' asset_* names are files inside a folder reachable as
/// `assets_href` relative to the page (already URL-safe or encoded here). Names and paths are
/// HTML-escaped; frames without an image show a note instead of a broken link.
std::string to_html(const CompareReport& report, const std::string& assets_href);

/// Writes to_html(report, <assets folder name>) to html_file. The images must already be in
/// html_assets_dir(html_file) (compare_paths with assets_dir set to it writes them).
void write_html(const std::filesystem::path& html_file, const CompareReport& report);

/// Text safe inside HTML element content and attribute values.
std::string html_escape(const std::string& text);

}  // namespace raintrace::compare
