// The HTML report opened in real headless Chromium: every image loads, nothing is fetched from
// the network, and the rendered page is not blank.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "compare/compare_run.h"
#include "compare/image_io.h"
#include "compare/report_html.h"
#include "compare/test_files.h"

namespace raintrace::compare {
namespace {

namespace fs = std::filesystem;
constexpr const char* kChromium = "/usr/bin/chromium";

std::string run(const std::string& command) {
  std::string out;
  FILE* pipe = popen((command + " 2>/dev/null").c_str(), "r");
  if (!pipe) return out;
  std::array<char, 4096> buf;
  while (fgets(buf.data(), int(buf.size()), pipe)) out += buf.data();
  pclose(pipe);
  return out;
}

std::string chromium(const fs::path& profile, const std::string& args) {
  return run(std::string("timeout 60 ") + kChromium +
             " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run"
             " --disable-background-networking --disable-component-update --disable-sync"
             " --user-data-dir=" +
             profile.string() + " " + args);
}

Image pattern(int w, int h, int shift) {
  Image img(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        img.at(x, y, c) = float(((x + shift) * 3 + y * 2 + c * 40) % 256) / 255.0f;
  return img;
}

TEST(HtmlReportInChromium, AllImagesLoadAndThePageIsNotBlank) {
  if (!fs::exists(kChromium)) GTEST_SKIP() << kChromium << " not found: browser test skipped";
  testing_support::TempDir tmp;
  const fs::path ra = tmp.path() / "ref", rb = tmp.path() / "out";
  fs::create_directories(ra);
  fs::create_directories(rb);
  for (int i = 1; i <= 3; ++i) {
    const std::string name = "frame 000" + std::to_string(i) + ".png";  // a space: URL-encoded
    write_image(ra / name, pattern(64, 36, 0));
    write_image(rb / name, pattern(64, 36, i - 1));
  }
  write_image(ra / "frame_only_ref.png", pattern(64, 36, 0));
  const fs::path html = tmp.path() / "report" / "report.html";
  fs::create_directories(html.parent_path());
  CompareOptions options;
  options.assets_dir = html_assets_dir(html);
  const auto report = compare_paths(ra, rb, options);
  write_html(html, report);

  // 3 frames × 3 images + the one-sided frame's reference = 10 images.
  std::ostringstream page_bytes;
  page_bytes << std::ifstream(html).rdbuf();
  const std::string page = page_bytes.str();
  const auto count = [](const std::string& text, const std::regex& re) {
    return std::distance(std::sregex_iterator(text.begin(), text.end(), re),
                         std::sregex_iterator());
  };
  ASSERT_EQ(count(page, std::regex("<img ")), 10);

  // Count the images that actually decoded: a script appended to a copy of the page sets the
  // title once the window has loaded; --dump-dom prints the DOM after the load event.
  const fs::path probe = html.parent_path() / "probe.html";
  std::ofstream(probe) << page
                       << "<script>window.addEventListener('load',()=>{const i=[...document."
                          "images];document.title='loaded '+i.filter(x=>x.complete&&x."
                          "naturalWidth>0).length+' of '+i.length;});</script>";
  const std::string dom =
      chromium(tmp.path() / "profile1", "--virtual-time-budget=5000 --dump-dom " + probe.string());
  EXPECT_NE(dom.find("<title>loaded 10 of 10</title>"), std::string::npos)
      << "Chromium's DOM title: " << dom.substr(0, 300);

  // A screenshot of the real page is not blank: its pixels vary.
  const fs::path shot = tmp.path() / "shot.png";
  chromium(tmp.path() / "profile2",
           "--window-size=1200,900 --screenshot=" + shot.string() + " " + html.string());
  ASSERT_TRUE(fs::exists(shot)) << "Chromium wrote no screenshot";
  const Image img = read_image(shot);
  EXPECT_EQ(img.width, 1200);
  float lo = 1, hi = 0;
  for (float v : img.pixels) lo = std::min(lo, v), hi = std::max(hi, v);
  EXPECT_GT(hi - lo, 0.5f) << "screenshot looks blank";
}

}  // namespace
}  // namespace raintrace::compare
