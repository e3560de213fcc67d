// develop(): the steps in the order of the light, settings checked by name, the PNG written
// atomically from exactly what develop() returns, the HDR input left alone.
#include "film/develop.h"

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "film/bloom.h"
#include "film/diffraction_spikes.h"
#include "film/exposure.h"
#include "film/grain.h"
#include "film/image_file.h"
#include "film/sensor_noise.h"
#include "film/softness.h"
#include "film/vignette.h"
#include "film/white_balance.h"
#include "tests/support/command.h"

namespace raintrace::film {
namespace {

namespace fs = std::filesystem;

const DisplayTransform& filmic() {
  static const DisplayTransform transform;
  return transform;
}

/// Everything off: develop is exposure and the curve alone.
DevelopSettings plain() {
  return {.exposure_ev = 0.0,
          .look = Look::medium_contrast,
          .bloom = 0.0,
          .grain = 0.0,
          .vignette = 0.0};
}

RgbImage ramp(int w, int h) {
  RgbImage image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        image.at(x, y, c) = float(std::exp2(double(x) / 4.0 - 10.0 + 0.5 * c + 0.1 * y));
  image.at(w / 2, h / 2, 0) = 500.0f;  // a lamp
  return image;
}

TEST(Develop, MiddleGreyAtZeroStopsIsHalfAndEachStopOfExposureCountsTwice) {
  RgbImage grey(4, 4, 0.18f), quarter(4, 4, 0.045f);
  EXPECT_NEAR(develop(grey, plain(), {}, filmic()).at(1, 1, 0), 0.5, 0.001);
  DevelopSettings two_stops = plain();
  two_stops.exposure_ev = 2.0;
  EXPECT_EQ(develop(quarter, two_stops, {}, filmic()).pixels,
            develop(grey, plain(), {}, filmic()).pixels);
}

TEST(Develop, RunsTheStepsInTheOrderOfTheLight) {
  const RgbImage linear = ramp(48, 20);
  const DevelopSettings settings{.exposure_ev = -1.5,
                                 .white_balance_k = 3500,
                                 .look = Look::high_contrast,
                                 .bloom = 0.2,
                                 .softness = 2.0,
                                 .grain = 0.1,
                                 .sensor_noise = 0.2,
                                 .vignette = 0.7,
                                 .aperture_blades = 5};
  const FrameContext frame{.fov_deg = 70.0, .seed = 9, .frame = 4, .aperture_m = 0.001};
  RgbImage by_hand = linear;
  apply_white_balance(by_hand, 3500);  // on the sensor's raw signal, as a camera does
  apply_exposure(by_hand, -1.5);
  apply_vignette(by_hand, 0.7, 70.0);
  apply_diffraction_spikes(by_hand, {5, 0.001}, 70.0);  // at the iris, before the glass's blur
  apply_softness(by_hand, 2.0);                         // the lens blurs before its glare scatters
  by_hand = bloom(by_hand, 0.2);
  apply_sensor_noise(by_hand, 0.2, 9, 4);  // the light reaching the sensor, before the curve
  by_hand = filmic().to_display(by_hand, View::filmic, Look::high_contrast);
  apply_grain(by_hand, 0.1, 9, 4);
  EXPECT_EQ(develop(linear, settings, frame, filmic()).pixels, by_hand.pixels);
}

TEST(Develop, ANanPixelStaysOneBlackPixel) {
  RgbImage linear(32, 32, 0.18f);
  linear.at(16, 16, 1) = std::numeric_limits<float>::quiet_NaN();
  DevelopSettings settings = plain();
  settings.bloom = 0.5;
  const RgbImage out = develop(linear, settings, {}, filmic());
  for (float v : out.pixels) ASSERT_FALSE(std::isnan(v));
  EXPECT_LT(out.at(16, 16, 1), 0.5f);
  EXPECT_NEAR(out.at(0, 0, 1), 0.5, 0.01);
}

TEST(Develop, ValidateNamesTheSettingOutOfRange) {
  const auto message = [](DevelopSettings s) {
    try {
      validate(s);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  DevelopSettings s;
  EXPECT_EQ(message(s), "(accepted)");
  s.exposure_ev = 20;
  EXPECT_NE(message(s).find("exposure_ev"), std::string::npos);
  s = {};
  s.white_balance_k = 1500;
  EXPECT_NE(message(s).find("white_balance_k"), std::string::npos);
  s.white_balance_k = 25000;
  EXPECT_NE(message(s).find("white_balance_k"), std::string::npos);
  s = {};
  s.bloom = -0.5;
  EXPECT_NE(message(s).find("bloom"), std::string::npos);
  s = {};
  s.grain = 0.9;
  EXPECT_NE(message(s).find("grain"), std::string::npos);
  s = {};
  s.softness = 5;
  EXPECT_NE(message(s).find("softness"), std::string::npos);
  s = {};
  s.sensor_noise = 0.6;
  EXPECT_NE(message(s).find("sensor_noise"), std::string::npos);
  s = {};
  s.vignette = 2;
  EXPECT_NE(message(s).find("vignette"), std::string::npos);
  s = {};
  s.aperture_blades = 2;
  EXPECT_NE(message(s).find("aperture_blades"), std::string::npos);
  s.aperture_blades = 17;
  EXPECT_NE(message(s).find("aperture_blades"), std::string::npos);
  s = {};
  s.view = View::standard;  // the look is Filmic's: the standard view ignores it
  s.look = Look::low_contrast;
  EXPECT_EQ(message(s), "(accepted)");
}

TEST(Develop, DescribeRecordsEverySetting) {
  const DevelopSettings s{.exposure_ev = -1.5,
                          .look = Look::low_contrast,
                          .bloom = 0.04,
                          .grain = 0.02,
                          .vignette = 0.3};
  EXPECT_EQ(describe(s),
            "raintrace develop: exposure_ev=-1.5 view=filmic look=low-contrast bloom=0.04 "
            "grain=0.02 vignette=0.3");
  EXPECT_EQ(describe({.view = View::standard, .look = Look::low_contrast}),
            "raintrace develop: exposure_ev=0 view=standard bloom=0.04 grain=0.02 vignette=0.5");
  EXPECT_EQ(describe(s, {.fov_deg = 42.5, .seed = 7, .frame = 16}),
            describe(s) + " fov_deg=42.5 seed=7 frame=16");
  // Softness and sensor noise are named only when on: pictures developed before keep their text.
  EXPECT_EQ(describe({.softness = 1, .grain = 0, .sensor_noise = 0.1}),
            "raintrace develop: exposure_ev=0 view=filmic look=medium-high-contrast bloom=0.04 "
            "softness=1 grain=0 sensor_noise=0.1 vignette=0.5");
  // So is the white balance, after the exposure.
  EXPECT_EQ(describe({.white_balance_k = 3500}),
            "raintrace develop: exposure_ev=0 white_balance_k=3500 view=filmic "
            "look=medium-high-contrast bloom=0.04 grain=0.02 vignette=0.5");
  // So are the iris's blades, and with them the opening the spikes need, after fov_deg.
  EXPECT_EQ(describe({.aperture_blades = 6}, {.fov_deg = 50, .frame = 3, .aperture_m = 0.008}),
            "raintrace develop: exposure_ev=0 view=filmic look=medium-high-contrast bloom=0.04 "
            "grain=0.02 vignette=0.5 aperture_blades=6 fov_deg=50 aperture_m=0.008 seed=1 frame=3");
  EXPECT_EQ(describe({}, {.fov_deg = 50, .frame = 3, .aperture_m = 0.008}),
            describe({}) + " fov_deg=50 seed=1 frame=3");
}

TEST(Develop, DescriptionReadsBackToTheSameSettingsAndFrame) {
  const DevelopSettings s{.exposure_ev = -1.0 / 3.0,
                          .look = Look::very_high_contrast,
                          .bloom = 0.1,
                          .grain = 0,
                          .vignette = 0.25};
  const FrameContext frame{.fov_deg = 1.0 / 7.0, .seed = 9223372036854775807ULL, .frame = 12345};
  const auto back = parse_description(describe(s, frame));
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(describe(back->settings, back->frame), describe(s, frame));
  EXPECT_EQ(back->settings.exposure_ev, s.exposure_ev);  // exact: shortest round-trip text
  EXPECT_EQ(back->frame.fov_deg, frame.fov_deg);
  EXPECT_EQ(back->frame.seed, frame.seed);
  const auto standard = parse_description(describe({.view = View::standard}, frame));
  ASSERT_TRUE(standard.has_value());
  EXPECT_EQ(standard->settings.view, View::standard);
  const auto noisy = parse_description(
      describe({.white_balance_k = 3250.5, .softness = 0.75, .sensor_noise = 0.15}, frame));
  ASSERT_TRUE(noisy.has_value());
  EXPECT_EQ(noisy->settings.white_balance_k, 3250.5);
  EXPECT_EQ(back->settings.white_balance_k, 0.0);  // not named: off
  EXPECT_EQ(noisy->settings.softness, 0.75);
  EXPECT_EQ(noisy->settings.sensor_noise, 0.15);
  EXPECT_EQ(back->settings.softness, 0.0);  // not named: none
  EXPECT_EQ(back->settings.sensor_noise, 0.0);
  EXPECT_EQ(back->settings.aperture_blades, 0);
  const auto starry =
      parse_description(describe({.aperture_blades = 7}, {.fov_deg = 50, .aperture_m = 0.004}));
  ASSERT_TRUE(starry.has_value());
  EXPECT_EQ(starry->settings.aperture_blades, 7);
  EXPECT_EQ(starry->frame.aperture_m, 0.004);
  // Not a description of ours, one without the frame, or with a value out of range.
  EXPECT_FALSE(parse_description("made with GIMP"));
  EXPECT_FALSE(parse_description(describe(s)));
  EXPECT_FALSE(parse_description(describe({.bloom = 2}, frame)));
  EXPECT_FALSE(parse_description(describe({.sensor_noise = 0.7}, frame)));
  EXPECT_FALSE(parse_description(describe({.white_balance_k = 100}, frame)));
  EXPECT_FALSE(parse_description(describe({.aperture_blades = 6}, frame)));  // no opening
  EXPECT_FALSE(parse_description(describe(s, frame) + " extra"));
}

class DevelopFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = raintrace::test_support::process_scratch_path("raintrace_develop");
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }

  /// Writes `image` as a half-float EXR, as POV-Ray's +FE does.
  fs::path write_exr(const RgbImage& image, const std::string& name) {
    const fs::path path = dir / name;
    auto out = OIIO::ImageOutput::create(path.string());
    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::HALF);
    EXPECT_TRUE(out->open(path.string(), spec));
    EXPECT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data()));
    EXPECT_TRUE(out->close());
    return path;
  }

  static std::string bytes_of(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
  }

  fs::path dir;
};

TEST_F(DevelopFile, PngHoldsDevelopsValuesRoundedTo8BitsAndTheExrIsUntouched) {
  const fs::path exr = write_exr(ramp(40, 12), "frame_0007.exr");
  const std::string exr_bytes = bytes_of(exr);
  const DevelopSettings settings{.exposure_ev = 0.5, .bloom = 0.1, .grain = 0.05, .vignette = 0.5};
  const FrameContext frame{.fov_deg = 60.0, .seed = 3, .frame = 7};
  const fs::path png = dir / "frame_0007.png";
  develop_file(exr, png, settings, frame, filmic());

  const RgbImage expected = develop(read_rgb_image(exr), settings, frame, filmic());
  auto in = OIIO::ImageInput::open(png.string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().format, OIIO::TypeDesc::UINT8);
  EXPECT_EQ(in->spec().nchannels, 3);
  EXPECT_EQ(in->spec().get_string_attribute("ImageDescription"), describe(settings, frame));
  std::vector<std::uint8_t> bytes(expected.pixels.size());
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, bytes.data()));
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    ASSERT_EQ(int(bytes[i]), int(std::lround(expected.pixels[i] * 255.0f))) << "value " << i;
  }
  EXPECT_EQ(bytes_of(exr), exr_bytes);
  // Only the two frames: no temporary file left behind.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2);
}

TEST_F(DevelopFile, SameFrameDevelopsToByteIdenticalPngs) {
  // No time stamp in the file (unlike POV-Ray's own PNGs): frames can be compared by bytes.
  const fs::path exr = write_exr(ramp(40, 12), "frame_0003.exr");
  const FrameContext frame{.seed = 5, .frame = 3};
  develop_file(exr, dir / "a.png", {}, frame, filmic());
  develop_file(exr, dir / "b.png", {}, frame, filmic());
  EXPECT_EQ(bytes_of(dir / "a.png"), bytes_of(dir / "b.png"));
}

TEST_F(DevelopFile, MissingInputIsAnErrorNamingTheFile) {
  try {
    develop_file(dir / "frame_0001.exr", dir / "frame_0001.png", {}, {}, filmic());
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("frame_0001.exr"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "frame_0001.png"));
}

}  // namespace
}  // namespace raintrace::film
