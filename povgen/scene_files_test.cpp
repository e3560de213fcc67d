// scene.inc / scene.pov / scene.ini text: frame numbering, quality, fog, and refusal of
// values that must not reach POV-Ray.
#include "povgen/scene_files.h"

#include <gtest/gtest.h>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>

#include "povgen/output_folder.h"
#include "tests/support/command.h"

namespace raintrace::povgen {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(SceneFiles, IniPadsFrameNumbersToFourDigitsWhateverTheCount) {
  // POV-Ray pads output numbers to Final_Frame's digits: 48 frames would give frame_01.png.
  ExportParams look;
  const std::string ini = ini_text(look, 48, "frame", "scene.pov", {1, 48});
  EXPECT_TRUE(contains(ini, "\nInput_File_Name=scene.pov\n"));
  EXPECT_TRUE(contains(ini, "\nOutput_File_Name=images/frame_\n"));
  EXPECT_TRUE(contains(ini, "\nInitial_Frame=1\nFinal_Frame=9999\n"));
  EXPECT_TRUE(contains(ini, "\nSubset_Start_Frame=1\nSubset_End_Frame=48\n"));
  EXPECT_TRUE(contains(ini, "\nLibrary_Path=.\n"));
  EXPECT_TRUE(contains(ini, "\nWidth=640\nHeight=360\n"));
  const std::string big = ini_text(look, 12000, "frame", "scene.pov", {1, 12000});
  EXPECT_TRUE(contains(big, "\nFinal_Frame=99999\n"));
  EXPECT_TRUE(contains(dispatcher_text("frame", 5), "str(frame_number, -5, 0)"));
}

TEST(SceneFiles, IniRendersTheFramesItIsGiven) {
  // A folder exported with --frames 3-5 holds only those: scene.ini must not ask for others.
  const std::string ini = ini_text(ExportParams{}, 48, "frame", "scene.pov", {3, 5});
  EXPECT_TRUE(contains(ini, "\nInitial_Frame=1\nFinal_Frame=9999\n"));
  EXPECT_TRUE(contains(ini, "\nSubset_Start_Frame=3\nSubset_End_Frame=5\n"));
  for (const FrameSubset bad : {FrameSubset{0, 2}, FrameSubset{5, 3}, FrameSubset{40, 49}}) {
    EXPECT_THROW(ini_text(ExportParams{}, 48, "frame", "scene.pov", bad), std::invalid_argument)
        << bad.first << "-" << bad.last;
  }
}

TEST(SceneFiles, TheSharedFilesHashDoesNotDependOnWhichFramesSceneIniRenders) {
  // Exporting frames 1-2 and then 3-4 into one folder must not make frames 1-2 look changed.
  namespace fs = std::filesystem;
  const fs::path dir = raintrace::test_support::process_scratch_path("raintrace_shared_files_hash");
  fs::remove_all(dir);
  const ExportParams look;
  const std::string first = write_shared_files(dir / "a", look, 48, dir, {1, 2});
  const std::string second = write_shared_files(dir / "b", look, 48, dir, {3, 4});
  EXPECT_EQ(first, second);
  EXPECT_TRUE(contains(read_file_bytes(dir / "b" / "scene.ini"), "\nSubset_Start_Frame=3\n"));
  fs::remove_all(dir);
}

TEST(SceneFiles, FramesAreRenderedAsOpenExrAndMasksAsPng) {
  ExportParams look;
  const std::string frames = ini_text(look, 4, "frame", "scene.pov", {1, 4});
  EXPECT_TRUE(contains(frames, "\nOutput_File_Type=E\n"));          // scene-linear half float
  EXPECT_TRUE(contains(frames, "oiiotool images/frame_0001.exr"));  // how to look without us
  EXPECT_TRUE(contains(ini_text(look, 4, "mask", "mask.pov", {1, 4}), "\nOutput_File_Type=N\n"));
  // Develop settings are not in any file POV-Ray reads: editing them re-renders nothing.
  EXPECT_FALSE(contains(frames, "exposure_ev ="));
}

TEST(SceneFiles, QualityPicksAntialiasing) {
  ExportParams look;
  look.quality = Quality::preview;
  EXPECT_TRUE(contains(ini_text(look, 1, "frame", "scene.pov", {1, 1}), "\nAntialias=off\n"));
  look.quality = Quality::final;
  const std::string final_ini = ini_text(look, 1, "frame", "scene.pov", {1, 1});
  EXPECT_TRUE(contains(final_ini, "\nAntialias=on\nSampling_Method=1\n"));
  EXPECT_TRUE(contains(final_ini, "\nJitter=off\n"));  // repeatable across runs and threads
  // Masks stay crisp: coverage, not antialiased edges.
  EXPECT_TRUE(contains(ini_text(look, 1, "mask", "mask.pov", {1, 1}), "\nAntialias=off\n"));
}

TEST(SceneFiles, ApertureFocusesOnLookAtAndReplacesAntialiasing) {
  ExportParams look;
  look.quality = Quality::final;
  EXPECT_FALSE(contains(scene_inc_text(look), "aperture"));  // a pinhole by default
  look.camera.look_at = {0.0, 0.5, 2.0};
  look.aperture_m = 0.004;
  const std::string inc = scene_inc_text(look);
  // POV-Ray's aperture value is twice the lens opening it blurs as (see focal_blur_text).
  EXPECT_TRUE(contains(inc, " aperture 0.008 blur_samples 64,256 focal_point <0,0.5,2> "));
  EXPECT_TRUE(contains(inc, " confidence 0.95 variance 1/8000 bokeh{pigment{"));
  // Focal blur samples each pixel many times: no antialiasing on top.
  EXPECT_TRUE(contains(ini_text(look, 1, "frame", "scene.pov", {1, 1}), "\nAntialias=off\n"));
  look.quality = Quality::preview;
  EXPECT_TRUE(contains(scene_inc_text(look), " blur_samples 8,16 "));
  EXPECT_TRUE(contains(scene_inc_text(look), " variance 1/2000"));
  // Blurring the rain alone is povgen's (frame_values.h): POV-Ray's camera stays a pinhole.
  look.focal_blur = FocalBlur::rain;
  look.quality = Quality::final;
  EXPECT_FALSE(contains(scene_inc_text(look), "aperture"));
  EXPECT_TRUE(contains(ini_text(look, 1, "frame", "scene.pov", {1, 1}), "\nAntialias=on\n"));
  look.focal_blur = FocalBlur::traced;
  look.aperture_m = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(scene_inc_text(look), std::invalid_argument);
  look.aperture_m = 2.0;
  EXPECT_THROW(scene_inc_text(look), std::invalid_argument);
}

TEST(SceneFiles, SceneIncDeclaresRtPreviewPerQuality) {
  // Environments test RT_Preview for their cheap stand-ins; guarded so a command-line
  // Declare=RT_Preview=… wins, and declared before the environment is included.
  ExportParams look;
  look.environment_plate = false;  // preview only, tested on its own below
  look.quality = Quality::preview;
  const std::string preview = scene_inc_text(look);
  EXPECT_TRUE(contains(preview, "\n#ifndef(RT_Preview) #declare RT_Preview=1; #end\n"));
  EXPECT_LT(preview.find("RT_Preview"), preview.find("#include \"environment.inc\""));
  look.quality = Quality::final;
  const std::string final_inc = scene_inc_text(look);
  EXPECT_TRUE(contains(final_inc, "\n#ifndef(RT_Preview) #declare RT_Preview=0; #end\n"));
  // Nothing else in scene.inc depends on the quality.
  const std::string line1 = "#ifndef(RT_Preview) #declare RT_Preview=1; #end\n";
  const std::string line0 = "#ifndef(RT_Preview) #declare RT_Preview=0; #end\n";
  std::string same = preview;
  same.replace(same.find(line1), line1.size(), line0);
  EXPECT_EQ(same, final_inc);
}

TEST(SceneFiles, DispatcherIncludesTheFrameByNumber) {
  EXPECT_EQ(dispatcher_text("frame", 4).substr(dispatcher_text("frame", 4).find("#version")),
            "#version 3.7;\n#include concat(\"frames/frame_\", str(frame_number, -4, 0), "
            "\".pov\")\n");
  EXPECT_THROW(dispatcher_text("x\"#system", 4), std::invalid_argument);
  EXPECT_THROW(ini_text(ExportParams{}, 1, "frame", "evil.pov", {1, 1}), std::invalid_argument);
}

TEST(SceneFiles, SceneIncHasTheCameraAndMaterials) {
  ExportParams look;
  look.width = 320;
  look.height = 240;
  const std::string inc = scene_inc_text(look);
  // Camera (0, 1.6, −5) → (0, 1.6, 0), aspect 320/240 = 1.333333, fov 60.
  EXPECT_TRUE(contains(inc,
                       "camera{perspective location <0,1.6,-5> look_at <0,1.6,0> "
                       "right x*1.333333 up y angle 60}"));
  EXPECT_TRUE(contains(inc, "#include \"raintrace_materials.inc\""));
  EXPECT_TRUE(contains(inc, "#include \"environment.inc\""));
  EXPECT_TRUE(contains(inc, "#declare RT_LightningLight=8;"));
  EXPECT_FALSE(contains(inc, "fog{fog_type 2"));  // no [fog]
  // The drop's scattering lobes, declared before the materials that use them.
  EXPECT_LT(inc.find("#declare RT_DropBrilliance="), inc.find("raintrace_materials.inc"));
  EXPECT_LT(inc.find("#declare RT_DropLobeBack="), inc.find("raintrace_materials.inc"));
  // The materials come after the environment, which may declare RT_RainSurround.
  EXPECT_LT(inc.find("environment.inc"), inc.find("raintrace_materials.inc"));
}

TEST(SceneFiles, RainMediumStartsWhereTheSimulatedRainEnds) {
  ExportParams look;
  look.rain.far_m = 7.0;
  look.environment_plate = false;
  const std::string inc = scene_inc_text(look);
  // 5 mm/h: δ-scaled extinction 3.55e-4 /m (sim/rain_medium.h); HG scattering of a quarter of
  // it (POV-Ray's light colour is E/π) with extinction 4, and emission of the surroundings.
  EXPECT_TRUE(contains(inc, "#declare RT_RainExtinction=0.000355"));
  EXPECT_TRUE(contains(inc, "scattering{5,RT_RainExtinction/4 eccentricity 0.76"));
  EXPECT_TRUE(contains(inc, " extinction 4}"));
  EXPECT_TRUE(contains(inc, "emission RT_RainExtinction*RT_RainSurround"));
  // Camera at z = −5 looking along +z: the half-space z >= 2 (depth 7), within 200 m.
  EXPECT_TRUE(contains(inc, "sphere{<0,1.6,-5>,200}\n plane{<0,0,-1>,-2}"));
  // Preview without a plate: the fog form, capped at 200 m (transmit e^−200σ); final: media,
  // unless the environment declares that the fog form is all the medium would add.
  EXPECT_TRUE(contains(inc,
                       "fog{fog_type 1 distance 1/RT_RainExtinction color rgb "
                       "RT_RainSurround transmit exp(-200*RT_RainExtinction)}"));
  EXPECT_TRUE(
      contains(inc,
               "#ifndef(RT_RainAsFog) #declare RT_RainAsFog=0; #end\n"
               "#if(RT_Preview | RT_RainAsFog)\nRT_RainFog()\n#else\nRT_RainMedium()\n#end\n"));
  // With the plate it is traced into the plate and left out of the frames that draw it.
  look.environment_plate = true;
  EXPECT_TRUE(contains(scene_inc_text(look), "#if(!RT_LightsOnly)\nRT_RainMedium()\n#end\n"));
  // No rain, or switched off: no medium.
  look.rain_medium = false;
  EXPECT_FALSE(contains(scene_inc_text(look), "media{"));
  look.rain_medium = true;
  look.rain.rate_mm_per_h = 0.0;
  EXPECT_FALSE(contains(scene_inc_text(look), "media{"));
}

TEST(SceneFiles, FogModes) {
  ExportParams look;
  look.fog.mode = FogMode::ground;
  look.fog.density_per_m = 0.05;
  look.fog.depth_m = 4.0;
  // distance = 1/density = 20 m: fog reaches 1 − e^-1 there.
  EXPECT_TRUE(contains(scene_inc_text(look), "fog{fog_type 2 distance 20 "));
  // A flash lights the ground mist too.
  EXPECT_TRUE(contains(scene_inc_text(look), "+RT_Flash*RT_LightningLight*RT_KeyLight/4*"));
  EXPECT_FALSE(contains(scene_inc_text(look), "RT_LampHaze"));
  EXPECT_TRUE(contains(scene_inc_text(look), "fog_alt 4 up y}"));
  // The environment's painted lamp haze is this fog where the lamps stand: it reads the fog's
  // density and depth, declared before it.
  const std::string ground = scene_inc_text(look);
  const auto environment = ground.find("#include \"environment.inc\"");
  EXPECT_LT(ground.find("#declare RT_GroundFogDensity=0.05;"), environment);
  EXPECT_LT(ground.find("#declare RT_GroundFogDepth=4;"), environment);
  look.fog.mode = FogMode::media;
  const std::string media = scene_inc_text(look);
  // Hollow container of radius depth around the camera; scattering 0.7·0.05 (written as a quarter
  // of it, taking four times that: POV-Ray's units), absorption 0.3·0.05.
  EXPECT_TRUE(contains(media, "sphere{<0,1.6,-5>,4 hollow"));
  EXPECT_TRUE(contains(media, "scattering{1,rgb 0.00875*"));
  EXPECT_TRUE(contains(media, " extinction 4}\n  absorption rgb 0.015"));
  EXPECT_TRUE(contains(media, "jitter 0"));
  // Media mist scatters the lamps' light to the side itself: the environment paints no cones,
  // only the droplets' forward lobes, for the medium's scattering tinted by its colour's mean
  // (0.035 · 0.65), declared before the environment reads them.
  const auto media_environment = media.find("#include \"environment.inc\"");
  EXPECT_LT(media.find("#declare RT_LampHaze=0.02275;"), media_environment);
  EXPECT_LT(media.find("#declare RT_LampCones=0;"), media_environment);
  EXPECT_LT(media.find("#declare RT_MediaExtinction=0.05;"), media_environment);
  EXPECT_LT(media.find("#declare RT_MediaDepth=4;"), media_environment);
  EXPECT_FALSE(contains(media, "RT_GroundFogDensity"));
  look.fog.density_per_m = 0.0;
  EXPECT_FALSE(contains(scene_inc_text(look), "absorption rgb"));
}

TEST(SceneFiles, EnvironmentPlateOnlyWhereItStandsInFaithfully) {
  ExportParams look;  // preview, night_street, no fog
  EXPECT_TRUE(environment_plate_applies(look));
  const std::string inc = scene_inc_text(look);
  EXPECT_TRUE(contains(inc, "file_exists(\"textures/environment_plate.exr\")"));
  EXPECT_TRUE(contains(inc, "image_map{exr \"textures/environment_plate.exr\" once}"));
  EXPECT_TRUE(contains(inc, "RT_Flash<=0 & !RT_Bolts"));
  EXPECT_TRUE(contains(inc, "max_extent(RT_Plate).x=image_width"));
  EXPECT_TRUE(contains(ini_text(look, 2, "frame", "scene.pov", {1, 2}), "povray plate.ini"));
  look.environment.name = "field";
  EXPECT_TRUE(environment_plate_applies(look));

  auto refused = [](auto change) {
    ExportParams changed;
    change(changed);
    EXPECT_FALSE(environment_plate_applies(changed));
    const std::string text = scene_inc_text(changed);
    EXPECT_FALSE(contains(text, "environment_plate"));
    EXPECT_TRUE(contains(text, "#include \"environment.inc\"\n"));
  };
  refused([](ExportParams& l) { l.quality = Quality::final; });
  refused([](ExportParams& l) { l.environment_plate = false; });
  refused([](ExportParams& l) { l.environment.name = "closeup"; });  // backdrop inside the rain
  refused([](ExportParams& l) { l.environment.include_path = "mine.inc"; });
  // Fog that dims the drawn rain by more than kPlateFogDimming: the plate holds the fog and
  // frames that draw it leave it out, so their drops would miss too much of it. The default
  // density, 0.03 /m, over the default 12 m of drawn rain takes 30 %.
  refused([](ExportParams& l) { l.fog.mode = FogMode::ground; });
  refused([](ExportParams& l) { l.fog.mode = FogMode::media; });
  // The plate went through the lens barrel's rim already; the frames' rays would pass it again.
  refused([](ExportParams& l) {
    l.aperture_m = 0.01;
    l.optical_vignetting = 0.5;
  });
  // Fog with density 0 is no fog: the plate applies again.
  ExportParams clear;
  clear.fog.mode = FogMode::media;
  clear.fog.density_per_m = 0.0;
  EXPECT_TRUE(environment_plate_applies(clear));
  // The default example's mist, 0.0075 /m over 6 m: 4.4 %. The plate holds it, so the frames
  // that draw the plate leave it out; the plate itself and frames traced whole keep it.
  ExportParams thin;
  thin.fog.mode = FogMode::ground;
  thin.fog.density_per_m = 0.0075;
  thin.rain.far_m = 6.0;
  EXPECT_TRUE(environment_plate_applies(thin));
  const std::string thin_text = scene_inc_text(thin);
  EXPECT_TRUE(contains(thin_text, "#if(!RT_LightsOnly)\nfog{fog_type 2 distance 133.3"));
  // Media mist as thin: its container around the camera is left out of those frames too.
  ExportParams thin_media = thin;
  thin_media.fog.mode = FogMode::media;
  EXPECT_TRUE(environment_plate_applies(thin_media));
  EXPECT_TRUE(contains(scene_inc_text(thin_media), "#if(!RT_LightsOnly)\nsphere{"));
  thin.rain.far_m = 7.0;  // 5.1 %
  EXPECT_FALSE(environment_plate_applies(thin));
  EXPECT_FALSE(contains(scene_inc_text(thin), "#if(!RT_LightsOnly)\nfog{"));
  EXPECT_TRUE(contains(scene_inc_text(thin), "fog{fog_type 2 distance 133.3"));
}

TEST(SceneFiles, PlateIniRendersTheEnvironmentAloneAtTheFramesSize) {
  ExportParams look;
  look.width = 320;
  look.height = 240;
  const std::string ini = plate_ini_text(look);
  EXPECT_TRUE(contains(ini, "\nInput_File_Name=plate.pov\n"));
  // HDR like the frames: lamps far above 1 reach the frames unclipped.
  EXPECT_TRUE(contains(ini, "\nOutput_File_Name=textures/environment_plate.exr\n"));
  EXPECT_TRUE(contains(ini, "\nOutput_File_Type=E\n"));
  EXPECT_TRUE(contains(ini, "\nWidth=320\nHeight=240\n"));
  EXPECT_TRUE(contains(ini, "\nAntialias=off\n"));
  EXPECT_TRUE(contains(plate_pov_text(), "#declare RT_NoPlate=1;\n#include \"scene.inc\""));
}

TEST(SceneFiles, RangesAreTheSceneFormatsOwn) {
  // povgen checks its params with the same table rows as the scene reader (it used to allow
  // fov in (0, 180) where the reader allowed (1, 170)).
  ExportParams look;
  look.camera.fov_deg = 175;
  try {
    scene_inc_text(look);
    ADD_FAILURE() << "fov 175 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "camera.fov_deg must be in (1, 170) (got 175)");
  }
  look = ExportParams{};
  look.fps = 300;
  EXPECT_THROW(ini_text(look, 48, "frame", "scene.pov", {1, 48}), std::invalid_argument);
  look = ExportParams{};
  look.fog.mode = static_cast<FogMode>(9);
  EXPECT_THROW(scene_inc_text(look), std::invalid_argument);
}

TEST(SceneFiles, HostileValuesAreRefused) {
  ExportParams look;
  look.camera.position.x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(scene_inc_text(look), std::invalid_argument);
  look = ExportParams{};
  look.fog.density_per_m = std::numeric_limits<double>::infinity();
  EXPECT_THROW(scene_inc_text(look), std::invalid_argument);
  look = ExportParams{};
  look.width = 10;
  EXPECT_THROW(scene_inc_text(look), std::invalid_argument);
  for (const char* name : {"night_street\"\n#system(\"rm -rf ~\")", "#fopen F \"/etc/passwd\" read",
                           "../../etc/passwd", "field\n", "", "NIGHT_STREET"}) {
    look = ExportParams{};
    look.environment.name = name;
    EXPECT_THROW(scene_inc_text(look), std::invalid_argument) << name;
  }
}

}  // namespace
}  // namespace raintrace::povgen
