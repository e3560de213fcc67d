// See cli_test_support.h.
#include "tests/cli_test_support.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>
#include <fstream>
#include <set>
#include <sstream>

#include "output/manifest.h"

namespace raintrace::clitest {
namespace {

namespace fs = std::filesystem;

// File names (relative) under dir/sub with the given extension.
std::set<std::string> files_in(const fs::path& dir, const std::string& sub,
                               const std::string& extension) {
  std::set<std::string> names;
  if (!fs::is_directory(dir / sub)) return names;
  for (const auto& entry : fs::directory_iterator(dir / sub)) {
    if (entry.is_regular_file() && entry.path().extension() == extension) {
      names.insert(sub + "/" + entry.path().filename().string());
    }
  }
  return names;
}

void expect_same_pixels(const fs::path& a, const fs::path& b) {
  OIIO::ImageBuf image_a{a.string()};
  OIIO::ImageBuf image_b{b.string()};
  const auto cmp = OIIO::ImageBufAlgo::compare(image_a, image_b, 0.0f, 0.0f);
  EXPECT_FALSE(cmp.error) << a << " vs " << b << ": " << image_a.geterror() << image_b.geterror();
  EXPECT_EQ(cmp.nfail, 0U) << a << " differs from " << b;
  EXPECT_EQ(cmp.maxerror, 0.0) << a << " differs from " << b;
}

}  // namespace

std::string read_all(const fs::path& path) {
  std::ifstream in{path, std::ios::binary};
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

render::ProcessSpec raintrace_spec(const std::vector<std::string>& args, const fs::path& log) {
  render::ProcessSpec spec;
  spec.argv = {RAINTRACE_BINARY};
  spec.argv.insert(spec.argv.end(), args.begin(), args.end());
  spec.log_path = log;
  return spec;
}

Run run_raintrace(const std::vector<std::string>& args, const fs::path& log,
                  const std::map<std::string, std::string>& env) {
  render::ProcessSpec spec = raintrace_spec(args, log);
  for (const auto& [name, value] : env) spec.env[name] = value;
  render::ChildProcess child{spec};
  Run r;
  r.exit_code = child.wait();
  r.output = read_all(log);
  return r;
}

fs::path write_scene(const fs::path& dir, int frames, const std::string& name, int seed,
                     const std::string& extra) {
  fs::create_directories(dir);
  const auto path = dir / name;
  std::ofstream{path} << "seed = " << seed << "\n[output]\nframes = " << frames
                      << "\nfps = 24\nwidth = 64\nheight = 36\nquality = \"preview\"\n"
                         "[camera]\nposition = [0, 1.6, -5]\nlook_at = [0, 1.3, 0]\n"
                         "fov_deg = 60\nexposure_s = 0.02\n"
                         "[rain]\nrate_mm_per_h = 5\nnear_m = 0.3\nfar_m = 2.5\n"
                         "[wind]\nvelocity_m_per_s = [0.8, 0, 0]\n"
                         "[environment]\nname = \"night_street\"\n"
                      << extra;
  return path;
}

void expect_same_as_clean_render(const fs::path& folder, const fs::path& clean) {
  EXPECT_EQ(files_in(folder, "frames", ".pov"), files_in(clean, "frames", ".pov"));
  for (const auto& name : files_in(clean, "frames", ".pov")) {
    EXPECT_EQ(read_all(folder / name), read_all(clean / name)) << name;
  }
  const auto images = files_in(clean, "images", ".png");
  EXPECT_FALSE(images.empty()) << clean;
  EXPECT_EQ(files_in(folder, "images", ".png"), images);
  for (const auto& name : images) {
    if (!fs::exists(folder / name)) continue;
    expect_same_pixels(folder / name, clean / name);
    // Developed PNGs carry no time stamp: the same EXR and settings give the same bytes.
    if (name.find("/frame_") != std::string::npos) {
      EXPECT_TRUE(read_all(folder / name) == read_all(clean / name)) << name << ": other bytes";
    }
  }
  const auto exrs = files_in(clean, "images", ".exr");
  EXPECT_EQ(files_in(folder, "images", ".exr"), exrs);
  for (const auto& name : files_in(clean, "frames", ".pov")) {
    const auto stem = fs::path{name}.stem().string();
    if (stem.rfind("frame_", 0) == 0) {
      EXPECT_EQ(exrs.count("images/" + stem + ".exr"), 1U) << name;
    }
  }
  for (const auto& name : exrs) {
    if (fs::exists(folder / name)) expect_same_pixels(folder / name, clean / name);
  }
  if (fs::exists(clean / "contact_sheet.png")) {
    expect_same_pixels(folder / "contact_sheet.png", clean / "contact_sheet.png");
  }
  EXPECT_EQ(fs::exists(folder / "animation.mp4"), fs::exists(clean / "animation.mp4"));
  const auto a = output::read_manifest(folder / "manifest.json");
  const auto b = output::read_manifest(clean / "manifest.json");
  EXPECT_EQ(a.identity, b.identity);
  ASSERT_EQ(a.frames.size(), b.frames.size());
  for (std::size_t i = 0; i < a.frames.size(); ++i) {
    EXPECT_EQ(a.frames[i].number, b.frames[i].number);
    EXPECT_EQ(a.frames[i].input_hash, b.frames[i].input_hash) << a.frames[i].number;
    EXPECT_EQ(a.frames[i].image.status, output::FrameStatus::rendered) << a.frames[i].number;
    EXPECT_EQ(a.frames[i].developed.develop_hash, b.frames[i].developed.develop_hash)
        << a.frames[i].number;
    EXPECT_FALSE(a.frames[i].developed.develop_hash.empty()) << a.frames[i].number;
  }
}

}  // namespace raintrace::clitest
