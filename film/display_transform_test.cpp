// The display transform keeps blacks, middle grey and highlights where display_transform.h says.
// Expected values for greys are derived here from Blender's own LUT files, independently of
// OpenColorIO: Filmic Log = (log2 x + 12.473931188) / 25 → desaturation cube (a grey stays grey:
// read its diagonal) → ÷ 0.66 → the 4096-entry base-contrast curve, linearly interpolated.
#include "film/display_transform.h"

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/support/command.h"

namespace raintrace::film {
namespace {

namespace fs = std::filesystem;

const fs::path kLutFolder = fs::path(kBlenderOcioConfig).parent_path() / "filmic";

/// The values between { and } of an .spi1d file (one component).
std::vector<double> read_spi1d(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string all = text.str();
  std::istringstream body(all.substr(all.find('{') + 1));
  std::vector<double> values;
  double v = 0.0;
  while (body >> v) values.push_back(v);
  return values;
}

/// The grey diagonal (i, i, i) → R of an .spi3d cube.
std::vector<double> read_spi3d_diagonal(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // "spilut 1.0"
  std::getline(in, line);  // "3 3"
  int n = 0;
  in >> n >> n >> n;
  std::vector<double> diagonal(std::size_t(n), 0.0);
  int i = 0, j = 0, k = 0;
  double r = 0.0, g = 0.0, b = 0.0;
  while (in >> i >> j >> k >> r >> g >> b) {
    if (i == j && j == k) diagonal[std::size_t(i)] = r;
  }
  return diagonal;
}

/// Linear interpolation of equally spaced samples over [0, 1], clamped.
double sample(const std::vector<double>& table, double t) {
  const double x = std::clamp(t, 0.0, 1.0) * double(table.size() - 1);
  const auto i = std::min(std::size_t(x), table.size() - 2);
  const double f = x - double(i);
  return table[i] * (1.0 - f) + table[i + 1] * f;
}

/// Filmic (base contrast) of a scene-linear grey, from the LUT files.
double filmic_grey(double x) {
  static const std::vector<double> cube =
      read_spi3d_diagonal(kLutFolder / "filmic_desat65cube.spi3d");
  static const std::vector<double> curve = read_spi1d(kLutFolder / "filmic_to_0-70_1-03.spi1d");
  const double log_t = x > 0.0 ? (std::log2(x) + 12.473931188) / 25.0 : 0.0;
  return sample(curve, sample(cube, log_t) / 0.66);
}

float display_of(const DisplayTransform& transform, float grey, View view = View::filmic,
                 Look look = Look::medium_contrast) {
  RgbImage image(1, 1, grey);
  return transform.to_display(image, view, look).at(0, 0, 0);
}

class Filmic : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { transform = new DisplayTransform(); }
  static void TearDownTestSuite() { delete transform; }
  static DisplayTransform* transform;
};
DisplayTransform* Filmic::transform = nullptr;

// The LUT interpolation inside OpenColorIO and here agree to ~1e-6 (measured); 1e-4 leaves room
// for OpenColorIO's own optimisation of the LUT chain, far below 8-bit's 1/255 = 0.0039.
constexpr double kLutTolerance = 1e-4;

TEST_F(Filmic, MiddleGreyIsHalfTheDisplayRange) {
  EXPECT_NEAR(filmic_grey(0.18), 0.500, 0.001);  // the derivation itself agrees with the header
  EXPECT_NEAR(display_of(*transform, 0.18f), filmic_grey(0.18), kLutTolerance);
}

TEST_F(Filmic, SceneBlackStaysBlack) {
  // Below half a step of 8-bit: black pixels stay 0 in the PNG.
  EXPECT_LT(display_of(*transform, 0.0f), 0.5 / 255.0);
  EXPECT_NEAR(display_of(*transform, 0.0f), filmic_grey(0.0), kLutTolerance);
}

TEST_F(Filmic, GreysMatchTheConfigurationsLutsFromBlackToBeyondWhite) {
  for (double x : {0.0005, 0.002, 0.01, 0.05, 0.18, 0.5, 1.0, 2.0, 4.0, 8.0, 11.52, 16.0, 100.0}) {
    EXPECT_NEAR(display_of(*transform, float(x)), filmic_grey(x), kLutTolerance) << "grey " << x;
  }
}

TEST_F(Filmic, HighlightsBelowSixAndAHalfStopsOverGreyAreNotClipped) {
  // 0.18 · 2^6 = 11.52 is six stops over grey: it must stay distinguishable from white in 8 bits;
  // 0.18 · 2^6.5 = 16.29 is Filmic's white.
  EXPECT_LT(display_of(*transform, 11.52f), 1.0 - 1.0 / 255.0);
  EXPECT_GT(display_of(*transform, 16.29f), 1.0 - 0.5 / 255.0);
  EXPECT_FLOAT_EQ(display_of(*transform, 1000.0f), 1.0f);
}

TEST_F(Filmic, IsStrictlyIncreasingUpToWhite) {
  // An eighth of a stop apart from just above Filmic's black, 0.18 · 2⁻¹⁰ = 2^−12.47, to 16:
  // every step brighter than the last. Below that floor everything is the same black.
  EXPECT_EQ(display_of(*transform, 1e-5f), display_of(*transform, 0.0f));
  double previous = -1.0;
  for (double stops = -12.375; std::exp2(stops) < 16.0; stops += 0.125) {
    const double v = display_of(*transform, float(std::exp2(stops)));
    EXPECT_GT(v, previous) << "at 2^" << stops;
    previous = v;
  }
}

TEST_F(Filmic, LooksAreAppliedDespiteOcioDisplayIgnoringThem) {
  // OpenImageIO 2.4's ociodisplay drops its `looks` argument with OpenColorIO 2: a look must
  // really change the picture. Every look keeps grey at 0.5; higher contrast darkens shadows
  // and brightens highlights, in the order of the enum.
  double previous_shadow = 1.0, previous_highlight = 0.0;
  for (Look look : {Look::very_low_contrast, Look::low_contrast, Look::medium_low_contrast,
                    Look::medium_contrast, Look::medium_high_contrast, Look::high_contrast,
                    Look::very_high_contrast}) {
    EXPECT_NEAR(display_of(*transform, 0.18f, View::filmic, look), 0.5, 0.002) << to_string(look);
    const double shadow = display_of(*transform, 0.005f, View::filmic, look);
    const double highlight = display_of(*transform, 2.0f, View::filmic, look);
    EXPECT_LT(shadow, previous_shadow - 0.003) << to_string(look);
    EXPECT_GT(highlight, previous_highlight + 0.003) << to_string(look);
    previous_shadow = shadow;
    previous_highlight = highlight;
  }
}

TEST_F(Filmic, StandardViewIsSrgbClippedAtWhite) {
  // sRGB encoding: 12.92·x below 0.0031308, 1.055·x^(1/2.4) − 0.055 above; 1 and more → 1.
  const auto srgb = [](double x) {
    return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
  };
  for (double x : {0.0, 0.002, 0.18, 0.5, 0.9}) {
    // Blender's sRGB is a 1-D LUT (srgb_inv.spi1d), so allow its interpolation error.
    EXPECT_NEAR(display_of(*transform, float(x), View::standard), srgb(x), 2e-3) << x;
  }
  EXPECT_FLOAT_EQ(display_of(*transform, 4.0f, View::standard), 1.0f);
  // Looks are Filmic's: the standard view ignores them.
  EXPECT_EQ(display_of(*transform, 0.5f, View::standard, Look::high_contrast),
            display_of(*transform, 0.5f, View::standard));
}

TEST_F(Filmic, SameBitsWhateverOpenImageIosThreadSetting) {
  RgbImage frame(97, 61);
  for (std::size_t i = 0; i < frame.pixels.size(); ++i) {
    frame.pixels[i] = float(std::exp2(double(i % 173) / 8.0 - 12.0));
  }
  OIIO::attribute("threads", 1);
  const RgbImage one = transform->to_display(frame, View::filmic, Look::high_contrast);
  OIIO::attribute("threads", 2);
  const RgbImage two = transform->to_display(frame, View::filmic, Look::high_contrast);
  OIIO::attribute("threads", 0);
  const RgbImage again = transform->to_display(frame, View::filmic, Look::high_contrast);
  EXPECT_EQ(one.pixels, two.pixels);
  EXPECT_EQ(one.pixels, again.pixels);
}

TEST_F(Filmic, ResponseTellsViewsAndLooksApartAndRepeats) {
  const RgbImage filmic = transform->response(View::filmic, Look::medium_high_contrast);
  EXPECT_EQ(filmic.pixel_count(), 12U * 12U * 12U);
  EXPECT_EQ(transform->response(View::filmic, Look::medium_high_contrast).pixels, filmic.pixels);
  EXPECT_NE(transform->response(View::filmic, Look::medium_contrast).pixels, filmic.pixels);
  EXPECT_NE(transform->response(View::standard, Look::medium_contrast).pixels, filmic.pixels);
}

TEST(FilmicConfig, MissingConfigurationNamesTheDebianPackage) {
  try {
    DisplayTransform transform("/nonexistent/blender/config.ocio");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("blender-data"), std::string::npos) << message;
    EXPECT_NE(message.find("/nonexistent/blender/config.ocio"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
  }
}

TEST(FilmicConfig, TheUsersOcioVariableDoesNotChangeThePicture) {
  // OpenImageIO reads $OCIO only when given no file; raintrace always names its file.
  const char* before = std::getenv("OCIO");
  const std::string saved = before ? before : "";
  ::setenv("OCIO", "/nonexistent/other.ocio", 1);
  const DisplayTransform transform;
  EXPECT_NEAR(display_of(transform, 0.18f), filmic_grey(0.18), kLutTolerance);
  if (before) {
    ::setenv("OCIO", saved.c_str(), 1);
  } else {
    ::unsetenv("OCIO");
  }
}

TEST(FilmicConfig, AnotherConfigurationIsRefusedByName) {
  // A valid OpenColorIO configuration without Filmic.
  const fs::path dir = raintrace::test_support::process_scratch_path("raintrace_film_other_config");
  fs::create_directories(dir);
  const fs::path config = dir / "config.ocio";
  std::ofstream(config) << "ocio_profile_version: 2\n"
                           "roles:\n  default: Linear\n  scene_linear: Linear\n"
                           "displays:\n  sRGB:\n    - !<View> {name: Raw, colorspace: Linear}\n"
                           "colorspaces:\n  - !<ColorSpace>\n    name: Linear\n"
                           "    family: linear\n    isdata: false\n";
  try {
    DisplayTransform transform(config);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("is not Blender's Filmic colour configuration"),
              std::string::npos)
        << e.what();
  }
  fs::remove_all(dir);
}

TEST(FilmicNames, SceneFileSpellingsRoundTrip) {
  for (Look look : {Look::very_low_contrast, Look::medium_contrast, Look::very_high_contrast}) {
    EXPECT_EQ(parse_look(to_string(look)), look);
  }
  EXPECT_EQ(to_string(Look::medium_high_contrast), "medium-high-contrast");
  EXPECT_EQ(parse_view("filmic"), View::filmic);
  EXPECT_EQ(parse_view("standard"), View::standard);
  EXPECT_FALSE(parse_look("Medium High Contrast").has_value());
  EXPECT_FALSE(parse_view("Filmic").has_value());
}

}  // namespace
}  // namespace raintrace::film
