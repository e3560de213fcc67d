// The two examples that answer a figure of the paper show what the figure shows, checked on
// pictures the real POV-Ray renders from `raintrace export` folders (label povray; skipped where
// povray is missing):
//  - thunderstorm (Fig. 1): a frame of the clip shows the lightning channel itself, a bright
//    line running down a good part of the picture, not just a brightening, and the channel
//    brings the camera as much light as a return stroke does;
//  - closeup (Fig. 5): the drop covers a large part of the frame and shows the scene behind it
//    upside down. The scene is replaced by closeup.inc's test card (RT_TestCard: a sky warm
//    above and blue below the line of sight to the drop), so "upside down" has one meaning;
//  - default (the paper's night street with streetlights): the wet road and its puddles mirror
//    the lit air around the lamps, not only the lamps themselves; the parked cars' rain beads
//    break the lamps' highlights into glints; the road mirrors the traffic signals' colour;
//    the rain shows as streaks in the cone of the lamp in view; seen from a camera lower than
//    its own, no chain of reflections runs on to max_trace_level (the paint once held one).
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tests/support/command.h"

namespace raintrace {
namespace {

namespace fs = std::filesystem;

bool have_povray() { return std::system("command -v povray >/dev/null 2>&1") == 0; }

struct Image {
  int width = 0;
  int height = 0;
  std::vector<float> rgb;
  [[nodiscard]] const float* at(int x, int y) const {
    return &rgb[3 * (static_cast<std::size_t>(y) * width + x)];
  }
  [[nodiscard]] float luma(int x, int y) const {
    const float* p = at(x, y);
    return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
  }
};

Image read_image(const fs::path& path) {
  Image image;
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) return image;
  image.width = in->spec().width;
  image.height = in->spec().height;
  image.rgb.resize(static_cast<std::size_t>(image.width) * image.height * 3);
  in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, image.rgb.data());
  return image;
}

using test_support::read_text;

// A fresh folder for `raintrace export` (which refuses a non-empty folder it did not make),
// unique to this process: sessions may share the temporary directory.
fs::path work_dir(const std::string& name) {
  const fs::path dir = test_support::process_scratch_path("raintrace_example_figures_test") / name;
  fs::remove_all(dir);
  fs::create_directories(dir.parent_path());
  return dir;
}

// `raintrace export SCENE -o DIR --frames RANGE`; its log beside DIR.
void export_scene(const fs::path& scene, const fs::path& dir, const std::string& frames) {
  const fs::path log = dir.string() + ".export.log";
  const std::string command = std::string{RAINTRACE_EXE} + " export '" + scene.string() + "' -o '" +
                              dir.string() + "' --frames " + frames + " >'" + log.string() +
                              "' 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << read_text(log);
}

// The same for examples/EXAMPLE.toml.
void export_example(const std::string& example, const fs::path& dir, const std::string& frames) {
  export_scene(fs::path{RAINTRACE_SOURCE_DIR} / "examples" / (example + ".toml"), dir, frames);
}

// Renders one scene file of the folder (path relative to it) into images/NAME.png, 16:9 like
// the examples, with extra POV-Ray options; into images/NAME.exr, scene-linear, if `exr`.
Image render(const fs::path& dir, const std::string& scene, const std::string& name, int width,
             const std::string& options, bool exr = false) {
  const std::string file = "images/" + name + (exr ? ".exr" : ".png");
  const std::string command = "cd '" + dir.string() + "' && povray " + scene + " +L. -D -A " +
                              (exr ? "+FE" : "+FN") + " +W" + std::to_string(width) + " +H" +
                              std::to_string(width * 9 / 16) + " +O" + file + " " + options +
                              " >povray.log 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << read_text(dir / "povray.log");
  return read_image(dir / file);
}

// How many pixels of the rectangle x0 <= x < x1, y0 <= y < y1 are brighter in `lighter` than in
// `base` by more than `by` (linear luma): what one change to the street added there.
int pixels_brighter(const Image& lighter, const Image& base, int x0, int x1, int y0, int y1,
                    float by) {
  int count = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      if (lighter.luma(x, y) - base.luma(x, y) > by) ++count;
    }
  }
  return count;
}

// Frame 1 of the default example exported into a fresh folder NAME and rendered twice at WIDTH
// as linear 16-bit PNG (plus OPTIONS): as exported, and with CHANGE, one more POV-Ray option (a
// `Declare=` that turns one thing of the street off or sets it otherwise). The folder is removed
// once both are read.
struct DefaultPair {
  Image as_exported;
  Image changed;
};
DefaultPair render_default_twice(const std::string& name, int width, const std::string& options,
                                 const std::string& change) {
  const fs::path dir = work_dir(name);
  export_example("default", dir, "1");
  const std::string linear = "+FN16 File_Gamma=1.0 " + options;
  DefaultPair pair{render(dir, "frames/frame_0001.pov", "as_exported", width, linear),
                   render(dir, "frames/frame_0001.pov", "changed", width, linear + " " + change)};
  EXPECT_EQ(pair.as_exported.width, width);
  EXPECT_EQ(pair.as_exported.rgb.size(), pair.changed.rgb.size());
  fs::remove_all(dir.parent_path());
  return pair;
}

// thunderstorm: writes frames/no_bolt.pov, the frame FILE (relative to the folder) cut where its
// bolt block starts, so it renders with the flash's light but without the bolt. False if FILE
// draws no bolt.
bool write_frame_without_bolt(const fs::path& dir, const std::string& file) {
  const std::string text = read_text(dir / file);
  const std::size_t bolt = text.find("#if(RT_Mask=0)\n");
  if (bolt == std::string::npos) return false;
  std::ofstream(dir / "frames" / "no_bolt.pov") << text.substr(0, bolt);
  return true;
}

// thunderstorm: every frame that draws a bolt, rendered as exported and again with its bolt
// block removed (the flash's light stays). The channel is where the bolt alone makes a pixel
// near white (≥ 0.9 after POV-Ray's clip to 1) that was at least 0.3 darker without it — the
// lit clouds behind reach ~0.3 at this exposure, so a brightening sky cannot pass for it. It
// must run down at least 20 % of the picture's height: a bolt seen from 500 m whose visible part
// spans the sky above the street, not a glint.
TEST(ExampleFigures, ThunderstormClipShowsTheLightningChannel) {
  if (!have_povray()) GTEST_SKIP() << "povray is not installed";
  const fs::path dir = work_dir("thunderstorm");
  // The example forces its first strike at 0.5 s: frames 13–20 at 24 fps hold its flash.
  export_example("thunderstorm", dir, "12-20");
  int frames_with_bolts = 0;
  double tallest = 0.0;
  for (int frame = 12; frame <= 20; ++frame) {
    const std::string file = "frames/frame_00" + std::to_string(frame) + ".pov";
    if (!write_frame_without_bolt(dir, file)) continue;
    ++frames_with_bolts;
    const Image with = render(dir, file, "with_" + std::to_string(frame), 320, "");
    const Image without = render(dir, "frames/no_bolt.pov", "without", 320, "");
    ASSERT_EQ(with.rgb.size(), without.rgb.size());
    ASSERT_FALSE(with.rgb.empty());
    int top = with.height, bottom = -1;
    for (int y = 0; y < with.height; ++y) {
      for (int x = 0; x < with.width; ++x) {
        if (with.luma(x, y) >= 0.9f && with.luma(x, y) - without.luma(x, y) >= 0.3f) {
          top = std::min(top, y);
          bottom = std::max(bottom, y);
        }
      }
    }
    if (bottom >= top) {
      tallest = std::max(tallest, static_cast<double>(bottom - top + 1) / with.height);
    }
  }
  EXPECT_GE(frames_with_bolts, 4) << "the forced strike's flash should last several frames";
  EXPECT_GE(tallest, 0.2) << "no frame shows a lightning channel across a fifth of the picture";
  fs::remove_all(dir.parent_path());
}

// thunderstorm: frame 13, the forced strike's brightest, rendered as scene-linear EXR with and
// without its bolt block. A return stroke radiates about 870 J per metre of channel (Krider,
// Dawson and Uman 1968); from 500 m through heavy rain, over a 1/50 s exposure, its visible part
// brings the camera tens of times the light of a street lamp 20 m away. So the light the bolt
// adds to the frame must at least equal all the rest of the frame's light (lamps, signs, the
// flash-lit street and sky) together, not be a thin line beside them.
TEST(ExampleFigures, ThunderstormBoltBringsTheCameraMoreLightThanTheWholeStreet) {
  if (!have_povray()) GTEST_SKIP() << "povray is not installed";
  const fs::path dir = work_dir("thunderstorm_light");
  export_example("thunderstorm", dir, "13");
  ASSERT_TRUE(write_frame_without_bolt(dir, "frames/frame_0013.pov"))
      << "frame 13 should draw the forced strike's bolt";
  const Image with = render(dir, "frames/frame_0013.pov", "with", 320, "", true);
  const Image without = render(dir, "frames/no_bolt.pov", "without", 320, "", true);
  ASSERT_EQ(with.rgb.size(), without.rgb.size());
  ASSERT_FALSE(with.rgb.empty());
  double added = 0.0, street = 0.0;
  for (int y = 0; y < with.height; ++y) {
    for (int x = 0; x < with.width; ++x) {
      added += with.luma(x, y) - without.luma(x, y);
      street += without.luma(x, y);
    }
  }
  EXPECT_GE(added, street) << "the bolt adds " << added / street
                           << " of the rest of the frame's light";
  fs::remove_all(dir.parent_path());
}

// Whether closeup's test card rendered two ways differs at (x, y) by more than 0.15 in a
// channel: the card's two colours differ by ~0.8, and focal blur at preview samples leaves ±0.05
// of grain on the card's edge.
bool card_differs(const Image& a, const Image& b, int x, int y) {
  const float* p = a.at(x, y);
  const float* q = b.at(x, y);
  return std::max({std::abs(p[0] - q[0]), std::abs(p[1] - q[1]), std::abs(p[2] - q[2])}) > 0.15f;
}

// closeup: the test card rendered with the drops and without them (RT_HeroDrops=0). The drops'
// footprint is where the two differ (card_differs). The big drop sits in the middle of the frame;
// the small beads lie outside its columns (the fine droplets, which lie in them too, are left out:
// RT_MistDrops=0). In the drop's columns: above the drop's middle row the card is warm, below it
// blue; inside the drop the order must be the other way round, as a lens that inverts the scene
// behind it shows it.
TEST(ExampleFigures, CloseupDropFillsTheFrameAndTurnsTheSceneUpsideDown) {
  if (!have_povray()) GTEST_SKIP() << "povray is not installed";
  const fs::path dir = work_dir("closeup");
  export_example("closeup", dir, "1");
  const std::string card = "Declare=RT_TestCard=1 Declare=RT_Preview=1 Declare=RT_MistDrops=0";
  const Image drops = render(dir, "frames/frame_0001.pov", "card_drops", 320, card);
  const Image bare =
      render(dir, "frames/frame_0001.pov", "card_bare", 320, card + " Declare=RT_HeroDrops=0");
  ASSERT_EQ(drops.rgb.size(), bare.rgb.size());
  ASSERT_FALSE(drops.rgb.empty());
  const int w = drops.width, h = drops.height;
  auto in_drop = [&](int x, int y) { return card_differs(drops, bare, x, y); };
  // Warm minus blue: > 0 on the card's upper half, < 0 on its lower half.
  auto warmth = [](const float* p) { return p[0] - p[2]; };

  // The big drop: the footprint in the middle 20 % of the columns, and its rows.
  const int x0 = w * 2 / 5, x1 = w * 3 / 5;
  int top = h, bottom = -1, covered = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (!in_drop(x, y)) continue;
      ++covered;
      if (x >= x0 && x < x1) {
        top = std::min(top, y);
        bottom = std::max(bottom, y);
      }
    }
  }
  ASSERT_GT(bottom, top) << "the drop changes nothing in the middle of the frame";
  // Designed: a 4.3 mm bead 28 mm from a 20° lens, ~43 % of the width and of the height.
  EXPECT_GE(static_cast<double>(covered) / (w * h), 0.12) << "the drop covers too little";
  EXPECT_GE(static_cast<double>(bottom - top + 1) / h, 0.25) << "the drop is too small";

  // Mean warmth of the drop's upper and lower thirds, inside the drop and on the bare card.
  double inside_upper = 0, inside_lower = 0, card_upper = 0, card_lower = 0;
  int n_upper = 0, n_lower = 0;
  const int third = (bottom - top + 1) / 3;
  for (int y = top; y <= bottom; ++y) {
    const bool upper = y<top + third, lower = y> bottom - third;
    if (!upper && !lower) continue;
    for (int x = x0; x < x1; ++x) {
      if (!in_drop(x, y)) continue;
      (upper ? inside_upper : inside_lower) += warmth(drops.at(x, y));
      (upper ? card_upper : card_lower) += warmth(bare.at(x, y));
      ++(upper ? n_upper : n_lower);
    }
  }
  ASSERT_GT(n_upper, 0);
  ASSERT_GT(n_lower, 0);
  inside_upper /= n_upper;
  inside_lower /= n_lower;
  card_upper /= n_upper;
  card_lower /= n_lower;
  std::printf("warmth: card upper %.3f lower %.3f, through the drop upper %.3f lower %.3f\n",
              card_upper, card_lower, inside_upper, inside_lower);
  // Pure card colours give ±0.75 (sRGB-encoded PNG). Measured: card +0.27 / −0.42 (the lens
  // blurs the card's split, which lies within the drop's rows), drop −0.53 / +0.57. Half of each
  // still has the right sign with room to spare.
  // The card as the lens sees it: warm above, blue below (the split runs through the drop).
  EXPECT_GT(card_upper, 0.13);
  EXPECT_LT(card_lower, -0.2);
  // Through the drop: blue above, warm below.
  EXPECT_LT(inside_upper, -0.25) << "the drop's upper part should show the card's lower half";
  EXPECT_GT(inside_lower, 0.25) << "the drop's lower part should show the card's upper half";
  fs::remove_all(dir.parent_path());
}

// closeup: the test card at preview with the fine droplets around the beads and without them
// (RT_MistDrops=0). They are the pixels where the two differ (card_differs), as for the big drop
// above: each droplet refracts the card turned over. 400 are scattered over 28 × 9 mm of paint,
// about a third of them within the frame's 9.9 mm at the drop, the smallest under a pixel (0.03
// mm at 320 pixels): there must be dozens of separate spots, none of them more than a few per
// cent of the big drop's 12 % of the frame, and none joined to the big drop's footprint (they
// keep 0.6 mm clear of its edge).
TEST(ExampleFigures, CloseupPaintIsPepperedWithFineDroplets) {
  if (!have_povray()) GTEST_SKIP() << "povray is not installed";
  const fs::path dir = work_dir("closeup_droplets");
  export_example("closeup", dir, "1");
  const std::string card = "Declare=RT_TestCard=1 Declare=RT_Preview=1";
  const Image with = render(dir, "frames/frame_0001.pov", "card_mist", 320, card);
  const Image without =
      render(dir, "frames/frame_0001.pov", "card_clear", 320, card + " Declare=RT_MistDrops=0");
  ASSERT_EQ(with.rgb.size(), without.rgb.size());
  ASSERT_FALSE(with.rgb.empty());
  const int w = with.width, h = with.height;
  std::vector<char> spot(static_cast<std::size_t>(w) * h, 0);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      spot[static_cast<std::size_t>(y) * w + x] = card_differs(with, without, x, y);
    }
  }
  // Connected spots (four neighbours), and the largest.
  int spots = 0;
  std::size_t largest = 0;
  std::vector<std::size_t> stack;
  for (std::size_t start = 0; start < spot.size(); ++start) {
    if (spot[start] != 1) continue;
    ++spots;
    std::size_t size = 0;
    stack.push_back(start);
    spot[start] = 2;
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      ++size;
      const int x = static_cast<int>(i % w), y = static_cast<int>(i / w);
      for (const auto& [dx, dy] :
           {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
        const int nx = x + dx, ny = y + dy;
        if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
        const std::size_t n = static_cast<std::size_t>(ny) * w + nx;
        if (spot[n] == 1) {
          spot[n] = 2;
          stack.push_back(n);
        }
      }
    }
    largest = std::max(largest, size);
  }
  std::printf("fine droplets: %d spots, the largest %zu pixels (%.2f %% of the frame)\n", spots,
              largest, 100.0 * static_cast<double>(largest) / (w * h));
  fs::remove_all(dir.parent_path());
  EXPECT_GE(spots, 30) << "too few fine droplets in view";
  EXPECT_LT(static_cast<double>(largest) / (w * h), 0.03) << "a droplet as big as a bead, or one "
                                                             "joined to the big drop";
}

// default: frame 1 rendered with the lamps' haze (night_street's RT_LampHaze, the rain-soaked
// air that makes each lamp a glow and a cone) and without it. The bottom fifth of the frame sees
// road nearer than any lamp, where the glow sheets stand: it can only show the haze in its
// mirror — puddles, the wet road's film. Linear 16-bit PNG, so the means are light. Before the
// glow was mirrored the two renders were equal there to the last bit; measured now: 7.2 %
// brighter (mirrors see the glow's core, RT_LampGlow in templates/night_street/streetlights.inc),
// the haze 0.0069 /m, the default's fog at the lamps' height; 12.0 % in 0.014 /m; 8.2 % while the
// road's film mirrored only half of what it reflects; 6.3 % before the droplets' diffraction
// halo; 2.4 % with haze 0.01 in a fog that stayed near the ground, 5.3 % with 0.02 in it.
TEST(ExampleFigures, DefaultStreetMirrorsTheLampsHazeInTheWetRoad) {
  if (!have_povray()) GTEST_SKIP() << "povray is not installed";
  const auto [haze, clear] = render_default_twice("default", 320, "", "Declare=RT_LampHaze=0");
  ASSERT_FALSE(haze.rgb.empty());
  ASSERT_EQ(haze.rgb.size(), clear.rgb.size());
  double with_haze = 0.0, without = 0.0;
  for (int y = haze.height * 4 / 5; y < haze.height; ++y) {
    for (int x = 0; x < haze.width; ++x) {
      with_haze += haze.luma(x, y);
      without += clear.luma(x, y);
    }
  }
  ASSERT_GT(without, 0.0);
  std::printf("near road with haze / without: %.4f\n", with_haze / without);
  EXPECT_GT(with_haze / without, 1.012) << "the wet road does not mirror the lamps' haze";
}

// default: frame 1 rendered with the traffic signals' halos and without (RT_SignalHalos 0), at
// 640×360 as linear 16-bit PNG. The two red signals before the cross street stand about 69 m
// off, at (249, 148) and (328, 150) of the frame; around each, 3 to 10 pixels out (0.3–1 m at
// that distance: past the signal's head and backing board, inside its halo's 4.9°), the red
// must rise by a tenth or more and the green by under a third as much: a red halo, drawn by
// the mist's forward lobes as the lamps' are. Measured on 2026-12-07 (the lenses blurred four
// times, the passer-by at z = 22): red ×1.62 and ×1.68, green ×1.07 and ×1.06; before, red ×1.55
// and ×1.70, green ×1.06 and ×1.06, the haze round them 0.0069 /m.
TEST(ExampleFigures, DefaultStreetSignalsGlowInTheMist) {
  if (!have_povray()) GTEST_SKIP() << "povray is not installed";
  const auto [halos, bare] =
      render_default_twice("default_signals", 640, "", "Declare=RT_SignalHalos=0");
  ASSERT_EQ(halos.width, 640);
  for (const auto& [cx, cy] : {std::pair{249, 148}, std::pair{328, 150}}) {
    double red = 0.0, red_bare = 0.0, green = 0.0, green_bare = 0.0;
    for (int y = cy - 10; y <= cy + 10; ++y) {
      for (int x = cx - 10; x <= cx + 10; ++x) {
        const int r2 = (x - cx) * (x - cx) + (y - cy) * (y - cy);
        if (r2 < 9 || r2 > 100) continue;
        red += halos.at(x, y)[0];
        red_bare += bare.at(x, y)[0];
        green += halos.at(x, y)[1];
        green_bare += bare.at(x, y)[1];
      }
    }
    ASSERT_GT(red_bare, 0.0);
    ASSERT_GT(green_bare, 0.0);
    std::printf("signal at (%d, %d): red ×%.3f, green ×%.3f with its halo\n", cx, cy,
                red / red_bare, green / green_bare);
    EXPECT_GT(red / red_bare, 1.1) << "no red halo around the signal at x " << cx;
    EXPECT_LT(green / green_bare - 1.0, (red / red_bare - 1.0) / 3.0)
        << "the halo around the signal at x " << cx << " is not the signal's red";
  }
}

// default: frame 1 at final quality (glass reflects only there) with the rain beads on the
// parked cars (night_street's RT_CarBeads) and with smooth, dry paint and glass. The beads are
// small curved mirrors: where the smooth car shows one broad highlight or none, the beaded one
// sends the lamps' glints to the camera from many points — pixels of the two nearest cars at
// least 0.05 brighter (linear; their body is ~0.02-0.05) with the beads than without. Measured:
// 21 of 9100 on 2026-12-07; 19 of 9100 on 2026-12-06, before and after the kebab house's sign
// became ANTALYA GRILL; 7 of 9100 on the paint since the kebab house's lit sign, which the beads
// mirror too, became the shorter KEBABS (33f6cd6); 13 before it; 27 while the sheets standing for
// the wet road's glossy streaks, which the beads mirror too, carried each streetlight's lens
// unforeshortened (3–6 times too bright); before that 22 when the beads covered all the paint (they
// stand in patches with smooth sheets of water between), 28 while the second car was grey rather
// than silver, 49 while the glass carried beads too, before it became clear enough to show the
// cabin (a beaded pane read as salt). 0 without beads, by construction.
TEST(ExampleFigures, DefaultStreetCarsGlintWithRainBeads) {
  if (!have_povray()) GTEST_SKIP() << "povray is not installed";
  const auto [wet, dry] =
      render_default_twice("default_cars", 640, "Declare=RT_Preview=0", "Declare=RT_CarBeads=0");
  ASSERT_EQ(wet.width, 640);
  ASSERT_EQ(wet.rgb.size(), dry.rgb.size());
  // The two cars nearest the camera, right of the road.
  const int pixels = (500 - 360) * (225 - 160);
  const int glints = pixels_brighter(wet, dry, 360, 500, 160, 225, 0.05f);
  std::printf("glints on the nearest cars: %d of %d pixels\n", glints, pixels);
  EXPECT_GE(glints, 4) << "the wet cars show no glints of their rain beads";
  EXPECT_LT(glints, pixels / 10) << "the beads glitter everywhere, not in the highlights";
}

// default: frame 1 with the traffic signals at the cross street showing red (night_street's
// RT_SignalAspect 0, the default) and green (2). The wet road between the camera and the
// signals mirrors each as a streak of its colour (RT_LampStreak): over the road below them
// (x 100–190, y 95–180 of 320×180, the signals standing near x 125 and 170, y 75) the
// red-minus-green of each pixel, summed, must be larger with red showing by a clear margin.
// Measured: 38.1 on 2026-12-07 (linear); 18.4 before (30.5 while every mirror saw each lens twice,
// the lens at full light and its streak); with the signals' RT_LampStreak removed, 0.05 (the lenses
// and their sharp mirror images alone).
TEST(ExampleFigures, DefaultStreetRoadMirrorsTheTrafficSignalsColour) {
  if (!have_povray()) GTEST_SKIP() << "povray is not installed";
  const auto [red, green] =
      render_default_twice("default_signals", 320, "", "Declare=RT_SignalAspect=2");
  ASSERT_EQ(red.width, 320);
  ASSERT_EQ(red.rgb.size(), green.rgb.size());
  double redder = 0.0;
  for (int y = 95; y < 180; ++y) {
    for (int x = 100; x < 190; ++x) {
      redder += (red.at(x, y)[0] - red.at(x, y)[1]) - (green.at(x, y)[0] - green.at(x, y)[1]);
    }
  }
  std::printf("road below the signals, red showing against green: %.3f\n", redder);
  EXPECT_GT(redder, 10.0) << "the wet road does not mirror the signals' colour";
}

// default: frame 1 with the pavements' shallow puddles (night_street's RT_PavementPuddles 0.5)
// and without them (0, the slabs only wet). Water darkens what lies under it, so a pavement
// pixel can only get brighter where the water mirrors something lit above it: the shop windows
// and fascias, the pharmacy's cross. Over the left pavement (x 0–220, y 184–294 of 640×360)
// at least 40 pixels must be brighter by 0.005 (linear; the slabs there are ~0.02–0.04).
// Measured: 1437 on 2026-12-07, 1436 on 2026-12-06; 75 when this test was written (92 while the
// puddles saw each lamp's lens twice, the lens at full light and its streak); with the water's
// reflection taken out, 0.
TEST(ExampleFigures, DefaultPavementPuddlesMirrorTheLitShops) {
  if (!have_povray()) GTEST_SKIP() << "povray is not installed";
  const auto [water, slabs] =
      render_default_twice("default_pavement", 640, "", "Declare=RT_PavementPuddles=0");
  ASSERT_EQ(water.width, 640);
  ASSERT_EQ(water.rgb.size(), slabs.rgb.size());
  const int mirrored = pixels_brighter(water, slabs, 0, 220, 184, 294, 0.005f);
  std::printf("left pavement pixels the puddles brighten: %d\n", mirrored);
  EXPECT_GE(mirrored, 40) << "the pavement's puddles mirror nothing";
}

// default: frame 1 at final quality (glass reflects only there) with the open shops' windows
// mirroring the street (night_street's RT_ShopMirror 1, the default) and with them clear glass
// only (0). Seen at 60–80° from their normal the panes reflect 7–40 % of the wet street, the
// lamps and the facades opposite, over the lit interior: the interior only ever gains light.
// Over the two shop windows in view (x 110–150 and 545–640, y 115–200 of 640×360) at least 900
// pixels must be brighter by 0.005 (linear), and hardly any darker. Measured: 2133 brighter, 15
// darker on 2026-12-07; 2056 and 15 on 2026-12-06; 1167 and 0 when this test was written; 1574 and
// 1 (a rain streak's antialiasing) while the glass saw each lamp's lens twice, the lens at full
// light and its streak; 1837 and 1 while the lamps' haze, which the glass mirrors too, was twice
// that.
TEST(ExampleFigures, DefaultStreetShopWindowsMirrorTheStreet) {
  if (!have_povray()) GTEST_SKIP() << "povray is not installed";
  const auto [mirror, clear] =
      render_default_twice("default_shops", 640, "Declare=RT_Preview=0", "Declare=RT_ShopMirror=0");
  ASSERT_EQ(mirror.width, 640);
  ASSERT_EQ(mirror.rgb.size(), clear.rgb.size());
  // Pixels of the two windows brighter in `lighter` than in `base` by 0.005.
  const auto over_windows = [](const Image& lighter, const Image& base) {
    return pixels_brighter(lighter, base, 110, 150, 115, 200, 0.005f) +
           pixels_brighter(lighter, base, 545, 640, 115, 200, 0.005f);
  };
  const int brighter = over_windows(mirror, clear);
  const int darker = over_windows(clear, mirror);
  std::printf("shop window pixels the mirror brightens: %d, darkens: %d\n", brighter, darker);
  EXPECT_GE(brighter, 900) << "the open shops' windows mirror nothing";
  EXPECT_LT(darker, brighter / 10) << "the shop glass hides its interior instead of adding to it";
}

// default: frame 1 with the passer-by crossing the street (night_street's RT_Passerby 1, the
// default) and without. Against the lamps' haze and the lit road the figure is a dark
// silhouette. Row by row from its top, the pixels it darkens by 0.002 (linear) in the box x
// 230–320, y 135–235 of 640×360 must make the shape of a person under an umbrella 28 m away,
// where 1 m is 24.5 pixels: a canopy 1 m across (at least 20 pixels wide in the top 8 rows;
// at 39 m, where it crossed until 2026-12-07, it was 16), then below the rim a body about
// 0.45 m wide (rows 10–42 at most 16 pixels wide, and 30 of those 33 darkened) down to the feet
// 46 rows below the top, where the figure's shadow on the road, 32 pixels wide, and the wet
// road's mirror image continue it. Measured: the canopy 22 pixels wide, the body at most 8, 33
// of 33 body rows.
TEST(ExampleFigures, DefaultStreetHasSomeoneCrossingUnderAnUmbrella) {
  if (!have_povray()) GTEST_SKIP() << "povray is not installed";
  const auto [street, empty] =
      render_default_twice("default_passerby", 640, "", "Declare=RT_Passerby=0");
  ASSERT_EQ(street.width, 640);
  // Per row of the box from the first the figure darkens: how many pixels it darkens.
  std::vector<int> widths;
  for (int y = 135; y < 235; ++y) {
    const int width = pixels_brighter(empty, street, 230, 320, y, y + 1, 0.002f);
    if (width > 0 || !widths.empty()) widths.push_back(width);
  }
  ASSERT_GE(widths.size(), 46u) << "nobody crosses the street, or the figure is too short";
  const int canopy = *std::max_element(widths.begin(), widths.begin() + 8);
  const int body = *std::max_element(widths.begin() + 10, widths.begin() + 43);
  const auto body_rows =
      std::count_if(widths.begin() + 10, widths.begin() + 43, [](int width) { return width > 0; });
  std::printf("passer-by: canopy %d pixels wide, body at most %d, %d of 33 body rows darkened\n",
              canopy, body, static_cast<int>(body_rows));
  EXPECT_GE(canopy, 20) << "no umbrella over the figure";
  EXPECT_LE(body, 16) << "the figure is too wide to be a person";
  EXPECT_GE(body_rows, 30) << "no body under the umbrella";
}

// Mean red over green of `image` in the rectangle x0 <= x < x1, y0 <= y < y1: how orange the
// light there is, whatever its brightness.
double red_over_green(const Image& image, int x0, int x1, int y0, int y1) {
  double red = 0.0;
  double green = 0.0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      red += image.at(x, y)[0];
      green += image.at(x, y)[1];
    }
  }
  return green > 0.0 ? red / green : 0.0;
}

// default: frame 1 with the street's mix of lamps (night_street's RT_LampMix 1, the default)
// and with every lamp the warm-white LED (0). The lamp on the left 40 m down is an old sodium
// lamp, ~2000 K (linear sRGB <1, 0.54, 0.18> at the LEDs' luma, against their <1, 0.78, 0.52>):
// the lit air just below its lens (x 253–263, y 103–109 of 640×360) must turn at least 25 %
// more orange, red over green, while the air below the warm LED 16 m down (x 227–237,
// y 28–34) stays within 3 %. Measured on 2026-12-07 (the lenses blurred four times, the passer-by
// at z = 22): 3.48 against 2.09 (+66 %), and 1.61 both times; before, 1.74 against 1.28 (+36 %),
// and 1.02 both times (1.72, 1.28 and 1.14 while the road's film mirrored only half of what it
// reflects).
TEST(ExampleFigures, DefaultStreetHasAnOldSodiumLampAmongItsLeds) {
  if (!have_povray()) GTEST_SKIP() << "povray is not installed";
  const auto [mixed, leds] = render_default_twice("default_lamps", 640, "", "Declare=RT_LampMix=0");
  ASSERT_EQ(mixed.width, 640);
  ASSERT_EQ(mixed.rgb.size(), leds.rgb.size());
  const double sodium = red_over_green(mixed, 253, 263, 103, 109);
  const double sodium_as_led = red_over_green(leds, 253, 263, 103, 109);
  const double led = red_over_green(mixed, 227, 237, 28, 34);
  const double led_alone = red_over_green(leds, 227, 237, 28, 34);
  std::printf("red/green below the sodium lamp %.3f (as an LED %.3f); below the LED %.3f (%.3f)\n",
              sodium, sodium_as_led, led, led_alone);
  EXPECT_GT(sodium, 1.25 * sodium_as_led) << "the sodium lamp's light is not orange";
  EXPECT_NEAR(led, led_alone, 0.03 * led_alone) << "the warm LED's light changed with the mix";
}

// Mean linear luma of `image` in the rectangle x0 <= x < x1, y0 <= y < y1.
double mean_luma(const Image& image, int x0, int x1, int y0, int y1) {
  double sum = 0.0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) sum += image.luma(x, y);
  }
  return sum / ((x1 - x0) * (y1 - y0));
}

// default: frame 1 with the lamps' aureole (night_street's RT_AureoleShare 0.5, the default)
// and without it (0). The mist's forward lobe lights the air around each lamp on every side,
// above its head too, where the downward cone of side-scattered light does not reach, and the
// halo fades with the angle from the lamp (∝ F(ρ/D)/ρ). The lamp on the right 28 m down the
// street, 34.5 m from the camera, has its lens at (360, 76) of 640×360; 1 m there is ~20 px.
// Just above its head (0.3–0.8 m, y 60–70) the air must gain more than 0.011 (linear luma; the
// air there is ~0.018 without the halo), and at least 2.5 times what it gains 1.3–1.8 m above
// (y 40–50). Measured on 2026-12-07 (the lenses blurred four times, the passer-by at z = 22):
// 0.0148 and 0.0053 (air 0.0753 without the halo); 0.0206 and 0.0046 (air 0.0982, lit by the
// droplets' diffraction halo; 0.0251 without it), the haze 0.014 /m, the mist the default's fog
// holds at the lamps' height, which also dims the lamp on its way to the camera; 0.0226 and 0.0051
// (air 0.0177) with haze 0.01 in a fog that stayed near the ground, 0.048, 0.012 and 0.033 with
// haze 0.02 in it; without the aureole (RT_AureoleShare 0 in both), 0.
TEST(ExampleFigures, DefaultStreetLampsHaveAnAureoleAboveTheirHeads) {
  if (!have_povray()) GTEST_SKIP() << "povray is not installed";
  const auto [halo, bare] =
      render_default_twice("default_aureole", 640, "", "Declare=RT_AureoleShare=0");
  ASSERT_EQ(halo.width, 640);
  ASSERT_EQ(halo.rgb.size(), bare.rgb.size());
  const double air = mean_luma(bare, 350, 371, 60, 70);
  const double near = mean_luma(halo, 350, 371, 60, 70) - air;
  const double far = mean_luma(halo, 350, 371, 40, 50) - mean_luma(bare, 350, 371, 40, 50);
  std::printf(
      "aureole over the lamp 28 m down: %.5f just above the head (air %.5f without), "
      "%.5f 1.3-1.8 m above\n",
      near, air, far);
  EXPECT_GT(near, 0.011) << "no halo above the lamp head";
  EXPECT_GT(near, 2.5 * far) << "the halo does not fade away from the lamp";
}

// default: frame 1 with the lamps' haze (RT_LampHaze, 0.014 /m: the default's fog at the lamps'
// height) and without it (0). A
// lamp's head and arm stand in its lit air, so they hide the glow behind them: with the haze,
// the air above and below the arm of the lamp 16 m down on the left (the arm runs from its pole
// at x 182 to its head at x 230, rising from rows 22-24 to 20-23 of 640×360; x 190-225 of rows
// 22-23 are arm all along, rows 16-19 and 26-29 air) gains light while the arm gains next to
// none. Its gain must stay under a quarter of the air's on either side. Measured: arm 0.0000,
// air above 0.041 and below 0.058 on 2026-12-07; air above 0.080 and below 0.129 (linear luma;
// 0.031 and 0.053 before the droplets' diffraction halo; 0.030 and 0.050 with haze 0.01 in a fog
// that stayed near the ground, 0.059 and 0.100 with 0.02 in it); while the glow sheet passed
// through the lens, in front of the arm, the arm gained 0.043 (air 0.064 and 0.105, that haze) and
// the heads seemed to float (blind viewers, every round).
TEST(ExampleFigures, DefaultStreetLampArmStandsDarkAgainstItsGlow) {
  if (!have_povray()) GTEST_SKIP() << "povray is not installed";
  const auto [haze, clear] = render_default_twice("default_arm", 640, "", "Declare=RT_LampHaze=0");
  ASSERT_EQ(haze.width, 640);
  ASSERT_EQ(haze.rgb.size(), clear.rgb.size());
  const auto gain = [&](int y0, int y1) {
    return mean_luma(haze, 190, 225, y0, y1) - mean_luma(clear, 190, 225, y0, y1);
  };
  const double arm = gain(22, 24);
  const double above = gain(16, 20);
  const double below = gain(26, 30);
  std::printf("haze's light on the lamp arm 16 m down: %.5f; air above %.5f, below %.5f\n", arm,
              above, below);
  EXPECT_GT(above, 0.015) << "no glow around the lamp head";
  EXPECT_GT(below, 0.015) << "no glow around the lamp head";
  EXPECT_LT(arm, 0.25 * std::min(above, below)) << "the glow is painted over the lamp's arm";
}

// default: frame 1 with the water film on wet paint, kerbs and plastic (night_street's
// RT_FilmIor 1.33, the default) and without it (1: POV-Ray's Fresnel reflection then stays at
// its minimum, as when an object has no interior). Fresnel's law only adds reflection toward
// grazing angles, so the film can only brighten: the parked cars' flanks and roofs, seen along
// the street, mirror the lamps and the lit air. Over the two nearest cars (x 360–500,
// y 160–225 of 640×360) at least 100 pixels must be brighter by 0.005 (linear), and next to
// none darker. Measured: 275 brighter, 0 darker on 2026-12-07; 168 and 0 before (212 while the
// paint saw each lamp's lens twice, the lens at full light and its streak); on the template before
// the film was given an interior (both renders alike), 0.
TEST(ExampleFigures, DefaultStreetWetPaintMirrorsMoreTowardGrazing) {
  if (!have_povray()) GTEST_SKIP() << "povray is not installed";
  const auto [film, bare] = render_default_twice("default_film", 640, "", "Declare=RT_FilmIor=1");
  ASSERT_EQ(film.width, 640);
  ASSERT_EQ(film.rgb.size(), bare.rgb.size());
  const int brighter = pixels_brighter(film, bare, 360, 500, 160, 225, 0.005f);
  const int darker = pixels_brighter(bare, film, 360, 500, 160, 225, 0.005f);
  std::printf("nearest cars' pixels the water film brightens: %d (darkens: %d)\n", brighter,
              darker);
  EXPECT_GE(brighter, 100) << "the wet paint's reflection does not grow toward grazing";
  EXPECT_LT(darker, 10) << "the film darkens the paint: Fresnel's law only adds reflection";
}

// `raintrace export` of the default example with each line of its scene file that starts with
// a key of `lines` replaced by that key's line, into DIR (the scene file beside it).
void export_default_with(const std::vector<std::pair<std::string, std::string>>& lines,
                         const fs::path& dir, const std::string& frames) {
  std::istringstream original(read_text(fs::path{RAINTRACE_SOURCE_DIR} / "examples/default.toml"));
  std::ostringstream changed;
  std::vector<int> replaced(lines.size(), 0);
  for (std::string row; std::getline(original, row);) {
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (row.rfind(lines[i].first, 0) == 0) {
        row = lines[i].second;
        ++replaced[i];
      }
    }
    changed << row << '\n';
  }
  for (std::size_t i = 0; i < lines.size(); ++i) {
    ASSERT_EQ(replaced[i], 1) << lines[i].first << " is not one line of examples/default.toml";
  }
  const fs::path scene = dir.string() + ".toml";
  std::ofstream(scene) << changed.str();
  export_scene(scene, dir, frames);
}

// The antialiasing lines of an exported folder's scene.ini, as POV-Ray command-line options.
std::string antialiasing_options_of(const fs::path& exported) {
  std::istringstream ini(read_text(exported / "scene.ini"));
  std::string options;
  for (std::string line; std::getline(ini, line);) {
    for (const char* key : {"Antialias", "Sampling_Method", "Jitter"}) {
      if (line.rfind(key, 0) == 0) options += " " + line;
    }
  }
  return options;
}

// The antialiasing of a final-quality export of the default: what `raintrace render` traces a
// final frame with.
std::string final_antialiasing_options() {
  const fs::path dir = work_dir("final_ini");
  export_default_with({{"quality =", "quality = \"final\""}}, dir, "1");
  const std::string options = antialiasing_options_of(dir);
  fs::remove_all(dir);
  return options;
}

// How many pixels of the rectangle are isolated glints: brighter (linear luma) than each of
// their four direct neighbours by half again and by more than `by`. (A streak of rain, one pixel
// wide, is no brighter than the pixels above and below it.)
int isolated_glints(const Image& image, int x0, int x1, int y0, int y1, float by) {
  int count = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const float brightest_neighbour = std::max(
          {image.luma(x - 1, y), image.luma(x + 1, y), image.luma(x, y - 1), image.luma(x, y + 1)});
      const float luma = image.luma(x, y);
      if (luma > 1.5f * brightest_neighbour && luma > brightest_neighbour + by) ++count;
    }
  }
  return count;
}

// default exported at final quality (no environment plate): frame 1 at 320×180, antialiased as
// a final frame, with the rain beyond far_m drawn as the street declares it (RT_RainAsFog: its
// fog form, which scatters no light, since the glows draw the lamps' share) and as media
// (Declare=RT_RainAsFog=0), which scatter the lights that still reach them. The two must differ
// (the switch works) by under 1 % of the mean luma on average: what the fog form leaves out is
// the sky's faint fill. Measured: 0.45 %; 0.34 % on frame 16 at 1280×720, where POV-Ray took
// 8 % less time with the fog form.
TEST(ExampleFigures, DefaultStreetRainMediumIsItsFogFormAtFinalQuality) {
  if (!have_povray()) GTEST_SKIP() << "povray is not installed";
  const fs::path dir = work_dir("default_rain_fog");
  export_default_with({{"quality =", "quality = \"final\""}}, dir, "1");
  ASSERT_NE(read_text(dir / "scene.inc").find("#if(RT_Preview | RT_RainAsFog)"), std::string::npos);
  const std::string antialiasing = antialiasing_options_of(dir);
  ASSERT_NE(antialiasing.find("Antialias=on"), std::string::npos) << antialiasing;
  const std::string options = "+FN16 File_Gamma=1.0 " + antialiasing;
  const Image fog = render(dir, "frames/frame_0001.pov", "fog", 320, options);
  const Image media =
      render(dir, "frames/frame_0001.pov", "media", 320, options + " Declare=RT_RainAsFog=0");
  ASSERT_EQ(fog.rgb.size(), media.rgb.size());
  double difference = 0.0, level = 0.0;
  for (int y = 0; y < fog.height; ++y) {
    for (int x = 0; x < fog.width; ++x) {
      difference += std::abs(fog.luma(x, y) - media.luma(x, y));
      level += media.luma(x, y);
    }
  }
  fs::remove_all(dir.parent_path());
  ASSERT_GT(level, 0.0);
  std::printf("rain as fog against media: mean |difference| %.4f of the mean luma\n",
              difference / level);
  EXPECT_GT(difference, 0.0) << "Declare=RT_RainAsFog=0 drew the same picture";
  EXPECT_LT(difference / level, 0.01) << "the fog form leaves out light the media scatter";
}

// default: frame 1 at final quality, antialiased as a final export is, with the wet ground's relief
// — the asphalt's aggregate and the puddles' rain roughness — drawn no finer than the pixels
// resolve (the ground include's RT_NoiseSpans 2, the default) and at its true scale
// (RT_NoiseSpans 0). Finer than a pixel, each antialiasing sample of a lamp's mirror image gets
// its own tilt and the road glitters with single-pixel glints (blind viewers: "render noise");
// resolved, the images break into patches a few pixels across. Over the road under the lamps'
// images (x 200–440, y 200–359 of 640×360) the resolved ground must show under 0.7 of the
// true scale's isolated glints, and fewer than 850. The ratio is the check: a glint here is a
// pixel brighter than its neighbours, and a wider mirrored lens raises both counts (more facets
// catch it, each fainter); the count's bound only catches the road turning to glitter
// everywhere. Measured: 654 resolved, 1102 at the true scale (0.59) with the passer-by at
// z = 22; 656 and 1091 (0.60) since mirrors see a
// streetlight's lens blurred over four times its half sizes, not twice (RT_LensBlur; both
// viewers of a blind pair saw "smeared, ripple-broken streaks" where twice gave "round, evenly
// sized sparkle dots", 2026-12-07); 451 and 785 (0.57), bounds 0.7 and 600, since the aggregate
// is a fractal (granite at 0.125) whose coarsest octave, the 8 mm stones, is drawn resolved and
// whose finer octaves sparkle within its patches: four of four blind viewers, two at 1280×720
// and two at 640×360, chose its long streaks of fine sparkle over the single octave's "scaly",
// "cell-like blobs" (2026-12-07). Until then the
// bounds were 0.45 and 250: the single octave of 8 mm at 0.2 showed 191 resolved, 728 at the true
// scale (0.26) since the final's antialiasing samples a pixel 2×2 at threshold 0.15; 200 and 604
// (0.33) since the relief is the stones' 8 mm at amount 0.2 (antialiasing 3×3 at 0.2): it
// breaks a lamp's image into a column of small glints, which five of six blind viewers chose
// over the 2 cm relief's smooth swells; 145 and 353 (0.41) at 2 cm and 0.1 since mirrors see
// each streetlight's lens blurred (RT_MirroredFlatLens: more of the facets catch it, each fainter,
// which blind viewers chose over glints "like identical stickers"); 110 and 266 (0.41) with the
// even copy of the lens; 99 and 305 while the rings were 17 mm long (the rain's roughness at its
// true scale is a noise of half a ring's wavelength, so the 31 mm rings made it coarser and it
// glitters less); 92 and 455 while the film mirrored only half of what it reflects; on the template
// before (the aggregate was POV-Ray's granite normal at its true scale), 143. The largest cluster
// of those left is on the puddles by the right kerb, where the rings are drawn.
TEST(ExampleFigures, DefaultStreetRoadImagesBreakIntoPatchesNotGlints) {
  if (!have_povray()) GTEST_SKIP() << "povray is not installed";
  const std::string antialiasing = final_antialiasing_options();
  ASSERT_NE(antialiasing.find("Antialias=on"), std::string::npos) << antialiasing;
  const auto [resolved, true_scale] = render_default_twice(
      "default_glints", 640, "Declare=RT_Preview=0" + antialiasing, "Declare=RT_NoiseSpans=0");
  ASSERT_EQ(resolved.width, 640);
  ASSERT_EQ(resolved.rgb.size(), true_scale.rgb.size());
  const int glints = isolated_glints(resolved, 200, 440, 200, 359, 0.02f);
  const int glitter = isolated_glints(true_scale, 200, 440, 200, 359, 0.02f);
  std::printf("isolated glints on the road: %d resolved, %d at the true scale\n", glints, glitter);
  EXPECT_LT(glints, 0.7 * glitter) << "the resolved ground glitters like one drawn at true scale";
  EXPECT_LT(glints, 850) << "the lamps' images on the road break into single-pixel glints";
}

// Fine vertical structure in a rectangle: the mean of |L(x) − (L(x − 1) + L(x + 1))/2| along
// rows (linear luma). Streaks a pixel or two wide raise it; smooth lit air does not.
double streak_texture(const Image& image, int x0, int x1, int y0, int y1) {
  double sum = 0.0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      sum += std::abs(image.luma(x, y) - 0.5 * (image.luma(x - 1, y) + image.luma(x + 1, y)));
    }
  }
  return sum / ((x1 - x0) * (y1 - y0));
}

// default: frame 1 exported as it is (`[rain] lamp_reach_m = 4`: the drops in a ball of 4 m in
// the air below and in front of the lamp 16 m down on the left are drawn, though they lie
// beyond far_m) and with lamp_reach_m = 0, rendered at 640×360 as exported. In the lamp's cone
// below its head (x 190–300, y 28–88 of 640×360: right of the pole, above the next lamp) the
// streaks must add fine vertical structure, at least twice that of the smooth medium alone,
// while the light there stays within 5 %: the streaks carry the rain's light that the medium
// carries, and the medium still fills the ball, so that share is counted twice. Measured:
// 0.00485 against 0.00087, light +4.1 % on 2026-12-07 (the lenses blurred four times, the
// passer-by at z = 22); 0.00461 against 0.00082, light +3.8 % in the mist of 0.0075 /m; 0.00518,
// 0.00106 and +4.3 % in 0.015 /m; 0.00599, 0.00156 and +2.5 % while the lamps' haze was twice that
// (the twice-counted share is a larger part of a thinner cone's light).
TEST(ExampleFigures, DefaultStreetRainShowsInTheLampsCone) {
  if (!have_povray()) GTEST_SKIP() << "povray is not installed";
  const fs::path drawn = work_dir("default_lamp_rain");
  const fs::path medium = work_dir("default_no_lamp_rain");
  export_example("default", drawn, "1");
  export_default_with({{"lamp_reach_m", "lamp_reach_m = 0"}}, medium, "1");
  const std::string linear = "+FN16 File_Gamma=1.0";
  const Image with = render(drawn, "frames/frame_0001.pov", "with", 640, linear);
  const Image without = render(medium, "frames/frame_0001.pov", "without", 640, linear);
  ASSERT_EQ(with.width, 640);
  ASSERT_EQ(with.rgb.size(), without.rgb.size());
  const double streaks = streak_texture(with, 190, 300, 28, 88);
  const double air = streak_texture(without, 190, 300, 28, 88);
  const double light = mean_luma(with, 190, 300, 28, 88) / mean_luma(without, 190, 300, 28, 88);
  std::printf(
      "fine structure in the lamp's cone: %.5f with its rain drawn, %.5f without; "
      "light %.4f of without\n",
      streaks, air, light);
  fs::remove_all(drawn.parent_path());
  EXPECT_GT(streaks, 2.0 * air) << "no streaks in the lamp's cone";
  EXPECT_NEAR(light, 1.0, 0.05) << "the drawn rain changes the cone's light, not only its grain";
}

// The number after `label` in POV-Ray's statistics, -1 if the log has none: "\nRays:" for the
// rays it traced, "Max Level:" for how deep they went (its "N/M").
long povray_statistic(const std::string& log, const std::string& label) {
  const std::size_t at = log.find(label);
  if (at == std::string::npos) return -1;
  return std::atol(log.c_str() + at + label.size());
}

// default with its camera at 1.0 m instead of 1.45 (look_at lowered with it), frame 16 at
// 320×180 final, antialiased through scene.ini as exported, with max_trace_level 20 instead of
// 32: rows 96–111, the road beyond the SLOW marking about 21 m ahead, where the water lies at
// grazing angles. A chain of reflections that doubles must not start there. Until the markings
// were hidden from reflected rays, one ran between the road and the paint's 2 mm edges on a spot
// of puddle shore, where the shore's blend traces a reflected ray for the film and another for
// the water, so it doubled at each level: one pixel took 496 143 rays at level 20 and the whole
// frame at level 32 never finished. A chain that does not double costs a ray a level and may go
// deep: since the road's film takes the rain's rings (2026-12-06) a few rays leave it nearly
// level and zig-zag between the two terraces' facades down the street, as between two mirrors,
// to level 20 (take away any one of the four terraces and the deepest ray goes 3–4 deep; 7 with
// the film's old undulation). So the rows' rays are counted: 87 445 as drawn (85 724 with the
// old undulation), 227 737 with the markings seen by mirrors again.
TEST(ExampleFigures, DefaultStreetSeenFromALowCameraEndsItsChainsOfReflections) {
  if (!have_povray()) GTEST_SKIP() << "povray is not installed";
  const fs::path dir = work_dir("default_low_camera");
  export_default_with({{"position", "position = [-1.2, 1.0, -6]"},
                       {"look_at", "look_at = [0.8, 0.4, 30]"},
                       {"width", "width = 320"},
                       {"height", "height = 180"},
                       {"quality", "quality = \"final\""}},
                      dir, "16");
  std::string settings = read_text(dir / "scene.inc");
  const std::size_t level = settings.find("max_trace_level 32");
  ASSERT_NE(level, std::string::npos) << "scene.inc sets no max_trace_level 32";
  settings.replace(level, std::string{"max_trace_level 32"}.size(), "max_trace_level 20");
  std::ofstream(dir / "scene.inc") << settings;
  const std::string command = "cd '" + dir.string() +
                              "' && povray scene.ini +SF16 +EF16 +SR96 +ER111 -D +GS " +
                              ">povray.log 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << read_text(dir / "povray.log");
  const std::string log = read_text(dir / "povray.log");
  const long deepest = povray_statistic(log, "Max Level:");
  const long rays = povray_statistic(log, "\nRays:");
  std::printf("rows of road 21 m ahead of a camera 1.0 m up: %ld rays, the deepest %ld of 20\n",
              rays, deepest);
  fs::remove_all(dir.parent_path());
  EXPECT_GT(deepest, 1) << "POV-Ray's statistics give no Max Level";
  EXPECT_GT(rays, 320 * 16) << "POV-Ray's statistics count fewer rays than the rows' pixels";
  EXPECT_LT(rays, 150000) << "a chain of reflections doubles";
}

}  // namespace
}  // namespace raintrace
