// End-to-end checks with the real POV-Ray (ctest label `povray`; skipped without povray):
// every template and fog mode parses and renders, preview differs from final only through
// RT_Preview, the environment plate stands in for the environment, scene.ini names images
// frame_NNNN.exr for a sub-range, masks are rain on black, renders repeat across thread counts,
// mist deepens.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "povgen/frame_text.h"
#include "povgen/frame_values.h"
#include "povgen/output_folder.h"
#include "povgen/povray_test_support.h"
#include "povgen/scene_files.h"
#include "povgen/test_support/synthetic_rain.h"

namespace raintrace::povgen {
namespace {

namespace fs = std::filesystem;

using testing::log_of;
using testing::read_rgb;
using testing::run_povray;

double mean_abs_difference(const std::vector<float>& a, const std::vector<float>& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += std::fabs(a[i] - b[i]);
  return sum / static_cast<double>(a.size());
}

double spread(const std::vector<float>& px) {
  const auto [lo, hi] = std::minmax_element(px.begin(), px.end());
  return *hi - *lo;
}

/// A folder with the shared files and frames 1..frames of synthetic rain (flash in frame 1).
fs::path make_folder(const std::string& name, ExportParams look, int frames = 1,
                     std::size_t drops = 3000) {
  const fs::path dir = testing::scratch_folder("povray_test_" + name);
  fs::remove_all(dir);
  write_shared_files(dir, look, frames, dir, {1, frames});
  for (int n = 1; n <= frames; ++n) {
    sim::Frame frame =
        test_support::synthetic_rain(drops, look.camera, double(look.width) / look.height, 12.0,
                                     1.0, static_cast<std::uint64_t>(n));
    frame.index = n;
    frame.splashes.position = {{0.2f, 0.01f, 1.0f}};
    frame.splashes.velocity = {{0.0f, 1.0f, 0.0f}};
    frame.splashes.diameter = {0.5e-3f};
    frame.splashes.opacity = {1.0f};
    if (n == 1) {
      frame.flash = 0.5f;
      sim::Bolt bolt;
      bolt.brightness = 0.5f;
      bolt.segments.push_back({{-40.0f, 120.0f, 150.0f}, {-35.0f, 40.0f, 150.0f}, 0.8f, 0});
      bolt.segments.push_back({{-35.0f, 40.0f, 150.0f}, {-42.0f, 0.0f, 150.0f}, 0.8f, 0});
      frame.bolts.push_back(bolt);
    }
    const std::string digits = frame_file_name("frame", n, frame_digits(frames), ".pov");
    write_file_atomic(dir / "frames" / digits, frame_text(build_frame_values(frame, look)));
    if (look.mask) {
      write_file_atomic(dir / "frames" / frame_file_name("mask", n, frame_digits(frames), ".pov"),
                        mask_text("frames/" + digits));
    }
  }
  return dir;
}

ExportParams tiny_look() {
  ExportParams look;
  look.width = 48;
  look.height = 27;
  return look;
}

TEST(PovRayTemplates, EveryEnvironmentAndFogModeRenders) {
  SKIP_WITHOUT_POVRAY();
  struct Case {
    const char* environment;
    FogMode fog;
  };
  const Case cases[] = {{"night_street", FogMode::off}, {"night_street", FogMode::media},
                        {"field", FogMode::off},        {"field", FogMode::ground},
                        {"closeup", FogMode::off},      {"closeup", FogMode::media}};
  for (const Case& c : cases) {
    ExportParams look = tiny_look();
    look.environment.name = c.environment;
    look.fog.mode = c.fog;
    const std::string name =
        std::string{c.environment} + "_" + std::to_string(static_cast<int>(c.fog));
    const fs::path dir = make_folder(name, look);
    ASSERT_EQ(run_povray(dir, "scene.ini"), 0) << name << ":\n" << log_of(dir);
    const auto px = read_rgb(dir / "images" / "frame_0001.exr");
    ASSERT_FALSE(px.empty()) << name;
    EXPECT_GT(spread(px), 0.1) << name << ": image is blank";
    fs::remove_all(dir);
  }
}

TEST(PovRayTemplates, PreviewVariantsRenderAndFinalIsTheSameSceneWithRtPreviewZero) {
  SKIP_WITHOUT_POVRAY();
  // Same flags and the same level of detail for streaks (left unset it differs by quality) for
  // both folders (no antialiasing), so only RT_Preview can tell them apart:
  // night_street's preview stand-ins change the picture, and a preview folder rendered with
  // Declare=RT_Preview=0 is the final scene pixel for pixel. Ground fog: the light sheets
  // must not hide it.
  for (const char* environment : {"night_street", "field", "closeup"}) {
    ExportParams look = tiny_look();
    look.environment.name = environment;
    look.fog.mode = FogMode::ground;
    look.min_streak_coverage = kFinalStreakCoverage;
    const std::string name = std::string{"quality_"} + environment;
    look.quality = Quality::preview;
    const fs::path preview = make_folder(name + "_preview", look);
    look.quality = Quality::final;
    const fs::path final_dir = make_folder(name + "_final", look);
    const std::string frame = "frames/frame_0001.pov +W48 +H27 +FN -A +L. +WT1 ";
    ASSERT_EQ(run_povray(preview, frame + "+Oimages/p.png"), 0) << name << log_of(preview);
    ASSERT_EQ(run_povray(preview, frame + "+Oimages/p0.png Declare=RT_Preview=0"), 0)
        << name << log_of(preview);
    ASSERT_EQ(run_povray(final_dir, frame + "+Oimages/f.png"), 0) << name << log_of(final_dir);
    const auto p = read_rgb(preview / "images" / "p.png");
    const auto f = read_rgb(final_dir / "images" / "f.png");
    ASSERT_FALSE(p.empty()) << name;
    EXPECT_GT(spread(p), 0.1) << name << ": preview image is blank";
    EXPECT_EQ(read_rgb(preview / "images" / "p0.png"), f) << name;
    if (std::string{environment} == "night_street") {
      EXPECT_NE(p, f) << "night_street's preview stand-ins changed nothing";
    }
    fs::remove_all(preview);
    fs::remove_all(final_dir);
  }
}

/// Writes a width×height half-float EXR of one colour (as POV-Ray's +FE writes a plate).
void write_solid_exr(const fs::path& path, int width, int height, float r, float g, float b) {
  std::vector<float> px;
  for (int i = 0; i < width * height; ++i) px.insert(px.end(), {r, g, b});
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out);
  ASSERT_TRUE(out->open(path.string(), OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::HALF)));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
  out->close();
}

TEST(PovRayPlate, FramesDrawThePlateInsteadOfTheEnvironmentWhereItIsFaithful) {
  SKIP_WITHOUT_POVRAY();
  // Frame 1 holds a bolt and a flash, frame 2 rain only. The third case is night_street in the
  // default example's thin mist, which the plate holds: a frame that draws the plate leaves the
  // mist out, or the mist would dim and light the view twice on its way to the plate.
  struct Case {
    const char* environment;
    double mist_per_m;
  };
  for (const Case c :
       {Case{"night_street", 0.0}, Case{"field", 0.0}, Case{"night_street", 0.0075}}) {
    ExportParams look = tiny_look();
    look.environment.name = c.environment;
    if (c.mist_per_m > 0.0) {
      look.fog.mode = FogMode::ground;
      look.fog.density_per_m = c.mist_per_m;
      look.rain.far_m = 6.0;
    }
    ASSERT_TRUE(environment_plate_applies(look));
    const std::string name =
        std::string{"plate_"} + c.environment + (c.mist_per_m > 0.0 ? "_mist" : "");
    const fs::path dir = make_folder(name, look, 2, 1500);
    ASSERT_TRUE(fs::exists(dir / "plate.ini")) << name;
    ASSERT_EQ(run_povray(dir, "plate.ini"), 0) << name << log_of(dir);
    const auto plate = read_rgb(dir / "textures" / "environment_plate.exr");
    ASSERT_EQ(plate.size(), 48u * 27u * 3u) << name;
    EXPECT_GT(spread(plate), 0.05) << name << ": the plate is blank";

    // Without rain a frame is its plate, pixel for pixel and value for value (HDR: lamps far
    // above 1 included): the plate lines up with the camera and passes through unchanged.
    write_file_atomic(dir / "frames" / "bare.pov",
                      "#declare RT_Flash=0;\n#include \"scene.inc\"\n");
    const std::string bare = "frames/bare.pov +W48 +H27 -A +L. +WT1 ";
    ASSERT_EQ(run_povray(dir, bare + "+FE +Oimages/bare.exr"), 0) << name << log_of(dir);
    EXPECT_EQ(read_rgb(dir / "images" / "bare.exr"), plate) << name;

    // With rain: close to the fully traced environment (what the plate leaves out is the rain
    // in the wet street's reflection and droplets the kerbs hide).
    const std::string frame2 = "frames/frame_0002.pov +W48 +H27 +FN -A +L. +WT1 ";
    ASSERT_EQ(run_povray(dir, frame2 + "+Oimages/plate2.png"), 0) << name << log_of(dir);
    ASSERT_EQ(run_povray(dir, frame2 + "+Oimages/full2.png Declare=RT_NoPlate=1"), 0) << name;
    const auto with_plate = read_rgb(dir / "images" / "plate2.png");
    const auto traced = read_rgb(dir / "images" / "full2.png");
    ASSERT_EQ(with_plate.size(), traced.size()) << name;
    EXPECT_LT(mean_abs_difference(with_plate, traced), 1.0 / 255.0) << name;

    // The lightning frame traces its environment whatever the plate holds; a rain frame shows
    // the plate's pixels. A plate of one flat colour tells the two apart.
    const std::string frame1 = "frames/frame_0001.pov +W48 +H27 +FN -A +L. +WT1 ";
    ASSERT_EQ(run_povray(dir, frame1 + "+Oimages/full1.png Declare=RT_NoPlate=1"), 0) << name;
    write_solid_exr(dir / "textures" / "environment_plate.exr", 48, 27, 1.0f, 0.0f, 1.0f);
    ASSERT_EQ(run_povray(dir, frame1 + "+Oimages/flat1.png"), 0) << name << log_of(dir);
    EXPECT_EQ(read_rgb(dir / "images" / "flat1.png"), read_rgb(dir / "images" / "full1.png"))
        << name;
    ASSERT_EQ(run_povray(dir, bare + "+FN +Oimages/flat_bare.png"), 0) << name << log_of(dir);
    const auto flat = read_rgb(dir / "images" / "flat_bare.png");
    ASSERT_FALSE(flat.empty());
    EXPECT_EQ(flat[0], 1.0f);
    EXPECT_EQ(flat[1], 0.0f);
    // A plate of another size (rendered by hand at another resolution) is not used.
    write_solid_exr(dir / "textures" / "environment_plate.exr", 24, 27, 1.0f, 0.0f, 1.0f);
    ASSERT_EQ(run_povray(dir, frame2 + "+Oimages/wrong2.png"), 0) << name << log_of(dir);
    EXPECT_EQ(read_rgb(dir / "images" / "wrong2.png"), traced) << name;
    fs::remove_all(dir);
  }
}

TEST(PovRayAnimation, SceneIniNamesImagesWithFourDigitsForAnySubRange) {
  SKIP_WITHOUT_POVRAY();
  // 48 frames: with Final_Frame=48 POV-Ray would write frame_02.exr. Frames 2-3 only, as
  // half-float OpenEXR (scene.ini's Output_File_Type=E: the frames stay scene-linear).
  const fs::path dir = make_folder("animation", tiny_look(), 48, 200);
  ASSERT_EQ(run_povray(dir, "scene.ini +SF2 +EF3"), 0) << log_of(dir);
  EXPECT_TRUE(fs::exists(dir / "images" / "frame_0002.exr"));
  EXPECT_TRUE(fs::exists(dir / "images" / "frame_0003.exr"));
  EXPECT_FALSE(fs::exists(dir / "images" / "frame_0001.exr"));
  EXPECT_FALSE(fs::exists(dir / "images" / "frame_02.exr"));
  EXPECT_FALSE(fs::exists(dir / "images" / "frame_0002.png"));
  auto in = OIIO::ImageInput::open((dir / "images" / "frame_0002.exr").string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().format, OIIO::TypeDesc::HALF);
  // frame_number picked the right file: frames 2 and 3 hold different rain.
  EXPECT_GT(mean_abs_difference(read_rgb(dir / "images" / "frame_0002.exr"),
                                read_rgb(dir / "images" / "frame_0003.exr")),
            0.0);
  fs::remove_all(dir);
}

TEST(PovRayMask, MaskIsRainWhiteOnBlack) {
  SKIP_WITHOUT_POVRAY();
  ExportParams look = tiny_look();
  look.mask = true;
  const fs::path dir = make_folder("mask", look, 1, 400);
  ASSERT_EQ(run_povray(dir, "mask.ini"), 0) << log_of(dir);
  const auto px = read_rgb(dir / "images" / "mask_0001.png");
  ASSERT_FALSE(px.empty());
  // White in proportion to the rain's coverage of each pixel: the share of its light the rain
  // replaces (faint for far streaks: a drop covers each point of its streak briefly).
  std::size_t black = 0;
  std::size_t rain = 0;
  bool grey = true;
  for (std::size_t i = 0; i < px.size(); i += 3) {
    if (px[i] == 0.0f) ++black;
    if (px[i] > 0.0f) ++rain;
    grey = grey && px[i] == px[i + 1] && px[i] == px[i + 2];
  }
  const std::size_t pixels = px.size() / 3;
  EXPECT_TRUE(grey) << "mask must be white on black, no colour";
  EXPECT_GT(black, pixels / 2) << "the environment leaked into the mask";
  EXPECT_GT(rain, 0u) << "no rain in the mask";
  fs::remove_all(dir);
}

TEST(PovRayDeterminism, SameFrameSamePixelsWithOneOrTwoThreads) {
  SKIP_WITHOUT_POVRAY();
  ExportParams look = tiny_look();
  look.fog.mode = FogMode::media;
  const fs::path dir = make_folder("threads", look);
  const std::string frame = "frames/frame_0001.pov +W48 +H27 +FN -A +L. ";
  ASSERT_EQ(run_povray(dir, frame + "+WT1 +Oimages/one.png"), 0) << log_of(dir);
  ASSERT_EQ(run_povray(dir, frame + "+WT2 +Oimages/two.png"), 0) << log_of(dir);
  const auto one = read_rgb(dir / "images" / "one.png");
  ASSERT_FALSE(one.empty());
  EXPECT_EQ(one, read_rgb(dir / "images" / "two.png"));
  fs::remove_all(dir);
}

// The start of a scene seen by the camera raintrace writes for a 200×200 picture from the
// origin along +z, 20° across, through a lens `aperture_m` wide focused 1 m away: its scene.inc
// camera line alone.
std::string scene_focused_at_one_metre(double aperture_m) {
  ExportParams look;
  look.width = look.height = 200;
  look.quality = Quality::final;
  look.camera.position = {0.0, 0.0, 0.0};
  look.camera.look_at = {0.0, 0.0, 1.0};
  look.camera.fov_deg = 20.0;
  look.aperture_m = aperture_m;
  const std::string inc = scene_inc_text(look);
  const std::size_t camera = inc.find("camera{");
  EXPECT_NE(camera, std::string::npos);
  if (camera == std::string::npos) return {};
  return "#version 3.7;\nglobal_settings{assumed_gamma 1}\n" +
         inc.substr(camera, inc.find('\n', camera) - camera) + "\n";
}

// A pixel of that picture at its plane of focus, 1 m away: 2·tan(10°) m over 200 pixels.
double pixel_at_the_focus_m() { return 2.0 * std::tan(10.0 * M_PI / 180.0) / 200.0; }

// [camera] aperture_m is the lens opening: a sharp edge 10 m away, seen by a camera focused at
// 1 m, blurs over a disc D = aperture_m · (10 − 1)/10 across at the plane of focus (thin-lens
// geometry). Measured in linear light (EXR) from where the bright side starts to dim (< 0.98) to
// where the dark side starts to brighten (> 0.02): a disc sliced by the edge covers 2 % of its
// area when the slice is 0.895 of its radius from the centre, so those points lie 0.895·D apart.
TEST(PovRayFocalBlur, AnEdgeBehindTheFocusBlursOverTheLensOpening) {
  SKIP_WITHOUT_POVRAY();
  const double aperture_m = 0.04;
  const fs::path dir = testing::empty_scratch_folder("povray_test_focal_blur");
  const auto px = testing::trace_linear(dir, "edge",
                                        scene_focused_at_one_metre(aperture_m) +
                                            "plane{-z,-10 pigment{function{x<0}} finish{ambient 0 "
                                            "diffuse 0 emission 1}}\n",
                                        "+W200 +H200 -A");
  ASSERT_EQ(px.size(), 200u * 200u * 3u);
  int first_dim = -1, last_lit = -1;
  for (int x = 0; x < 200; ++x) {
    // Average a band of rows: focal blur samples leave a little grain on single pixels.
    float v = 0.0f;
    for (int y = 90; y < 110; ++y) v += px[3 * (y * 200 + x)] / 20.0f;
    if (first_dim < 0 && v < 0.98f) first_dim = x;
    if (v > 0.02f) last_lit = x;
  }
  const double spread = (last_lit - first_dim + 1) * pixel_at_the_focus_m();
  // ±10 %: a pixel at each end is 5 % of the ~18 pixels, the rest focal-blur grain.
  EXPECT_NEAR(spread, 0.895 * aperture_m * 0.9, 0.1 * 0.895 * aperture_m * 0.9)
      << "edge spread " << spread;
  fs::remove_all(dir);
}

// A line 1.1 pixels thin and 10 m away, 51 pixels out of focus: every pixel shoots its rays
// through the same points of the lens, so the blur is that many sharp copies of the line. Its
// light must spread over the whole opening, its middle rows all lit, and reach the picture: POV-Ray
// stops a pixel whose first samples all missed the line, black. Without the bokeh pigment
// (focal_blur_text) the copies stood in the level rows of POV-Ray's hexagonal grid: 11 of the
// middle 32 rows dark, 44 rows lit of 51, 48 % of the light; with it and 32 samples, 1 of 38
// dark and 60 %; with 64, none dark and 83 %.
TEST(PovRayFocalBlur, AThinLineOutOfFocusSpreadsOverTheOpeningAndKeepsItsLight) {
  SKIP_WITHOUT_POVRAY();
  const double aperture_m = 0.1;
  const fs::path dir = testing::empty_scratch_folder("povray_test_focal_blur_line");
  // 2 m long, so the middle columns see all of the blurred line; 2 cm across, 10 m away.
  const double line_m = 0.02;
  const auto px = testing::trace_linear(
      dir, "line",
      scene_focused_at_one_metre(aperture_m) +
          "box{<-1,-0.01,10>,<1,0.01,10.01> pigment{rgb 1} finish{ambient 0 diffuse 0 "
          "emission 1}}\n",
      "+W200 +H200 -A");
  ASSERT_EQ(px.size(), 200u * 200u * 3u);
  // The light of each row, averaged over the middle 40 columns.
  std::vector<double> rows(200, 0.0);
  for (int y = 0; y < 200; ++y) {
    for (int x = 80; x < 120; ++x) rows[y] += px[3 * (y * 200 + x) + 1] / 40.0;
  }
  int first = -1, last = -1;
  for (int y = 0; y < 200; ++y) {
    if (rows[y] > 0.0 && first < 0) first = y;
    if (rows[y] > 0.0) last = y;
  }
  ASSERT_GE(first, 0) << "the line is not in the picture";
  // The opening's disc at the plane of focus: aperture_m · (10 − 1)/10.
  const double pixel = pixel_at_the_focus_m();
  const double disc_px = aperture_m * 0.9 / pixel;
  EXPECT_NEAR(last - first + 1, disc_px, 0.1 * disc_px) << "rows lit " << first << "–" << last;
  // The middle 70 % of the lit rows, where the disc's chords are long: none of them dark.
  const int margin = static_cast<int>(0.15 * (last - first + 1));
  double middle = 0.0;
  for (int y = first + margin; y <= last - margin; ++y) middle += rows[y];
  middle /= last - first + 1 - 2 * margin;
  int dark = 0;
  for (int y = first + margin; y <= last - margin; ++y) dark += rows[y] < 0.25 * middle ? 1 : 0;
  EXPECT_EQ(dark, 0) << "rows of dashes: " << dark << " dark rows in the middle";
  // The line's light: its height in pixels at emission 1.
  double light = 0.0;
  for (double r : rows) light += r;
  const double line_px = line_m / 10.0 / pixel;
  EXPECT_GT(light, 0.75 * line_px) << "the blurred line keeps " << light / line_px;
  EXPECT_LT(light, 1.05 * line_px) << "the blurred line keeps " << light / line_px;
  fs::remove_all(dir);
}

TEST(PovRayMist, MistDeepensWithDensityAndDepth) {
  SKIP_WITHOUT_POVRAY();
  // The further the picture moves from the fog-free one, the deeper the mist: the difference
  // must grow with density and with the depth of the foggy slab.
  auto render = [](const std::string& name, double density, double depth) {
    ExportParams look = tiny_look();
    look.environment.name = "field";
    look.fog.mode = density > 0 ? FogMode::media : FogMode::off;
    look.fog.density_per_m = density;
    look.fog.depth_m = depth;
    const fs::path dir = make_folder("mist_" + name, look, 1, 100);
    EXPECT_EQ(run_povray(dir, "scene.ini"), 0) << log_of(dir);
    auto px = read_rgb(dir / "images" / "frame_0001.exr");  // scene-linear: the mist's own light
    fs::remove_all(dir);
    return px;
  };
  const auto clear = render("clear", 0.0, 20.0);
  const auto light = render("light", 0.02, 20.0);
  const auto dense = render("dense", 0.2, 20.0);
  const auto deep = render("deep", 0.02, 200.0);
  ASSERT_FALSE(clear.empty());
  const double d_light = mean_abs_difference(clear, light);
  EXPECT_GT(d_light, 0.005);
  EXPECT_GT(mean_abs_difference(clear, dense), 2.0 * d_light);
  EXPECT_GT(mean_abs_difference(clear, deep), 1.5 * d_light);
}

}  // namespace
}  // namespace raintrace::povgen
