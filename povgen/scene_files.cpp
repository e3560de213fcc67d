// Text of scene.inc, scene.pov and scene.ini.
#include "povgen/scene_files.h"

#include <cmath>
#include <glm/common.hpp>
#include <stdexcept>
#include <string>

#include "povgen/frame_text.h"
#include "povgen/ground_scene.h"
#include "povgen/lens_barrel.h"
#include "povgen/number_format.h"
#include "povgen/rain_look.h"
#include "povgen/templates.h"

namespace raintrace::povgen {
namespace {

// Of the media mist's extinction, the share its droplets scatter; the rest they absorb.
constexpr double kMediaScatteringShare = 0.7;

std::string fog_text(const FogParams& fog, const sim::Camera& camera) {
  std::string text;
  if (fog.mode == FogMode::off || fog.density_per_m <= 0.0) return text;
  const std::string colour = format_vector(glm::clamp(fog.colour, 0.0, 1.0));
  if (fog.mode == FogMode::ground) {
    // Ground fog: full density below the ground, thinning with height over depth_m. POV-Ray's
    // `distance` is where fog reaches 63 % (e^-1), i.e. 1 / extinction.
    // A flash lights the mist: the light of RT_LightningLight·RT_KeyLight scattered by a cloud
    // of droplets that scatters about a quarter of it toward the camera.
    text += "fog{fog_type 2 distance " + format_number(1.0 / fog.density_per_m) + " color rgb " +
            colour + "+RT_Flash*RT_LightningLight*RT_KeyLight/4*<0.85,0.88,1>" +
            " fog_offset 0 fog_alt " + format_number(fog.depth_m) + " up y}\n";
    return text;
  }
  // Media mist: a hollow sphere of radius depth_m around the camera (the camera must be inside
  // a hollow container or media silently does nothing). Extinction = scattering + absorption =
  // density; 70 % of it scatters light from the environment's lights (streetlight cones),
  // 30 % absorbs (Lambert-Beer). The scattering is written as a quarter with `extinction 4`:
  // POV-Ray adds Sc·P·C per metre for a light of colour C, its phase function P integrating to
  // 4π and C standing for E/π, where physics adds σs·E·P/4π = σs/4·C·P (rain_look.h does the
  // same). Written whole, the mist shone four times as brightly as the lamps light it. Eight evenly
  // spaced samples (method 2) without jitter, which keeps renders repeatable: method 3's three
  // adaptive samples cost as much and drew each lamp's lit air as a column with a hard vertical
  // edge (heavy_fog, frame 16: mean error 0.057 against 32 samples, 0.0007 for these;
  // BENCHMARKS.md). The container's surface has no diffuse and no ambient: POV-Ray then skips its
  // light loop.
  const double scattering = kMediaScatteringShare * fog.density_per_m;
  const double absorption = (1.0 - kMediaScatteringShare) * fog.density_per_m;
  text += "sphere{" + format_vector(camera.position) + "," + format_number(fog.depth_m) +
          " hollow\n texture{pigment{rgbt 1} finish{ambient 0 diffuse 0}}\n"
          " interior{media{method 2 intervals 1 samples 8,8"
          " jitter 0\n  scattering{1,rgb " +
          format_number(scattering / 4.0) + "*" + colour + " extinction 4}\n  absorption rgb " +
          format_number(absorption) + "\n  emission RT_Flash*" +
          format_number(0.05 * fog.density_per_m) + "*" + colour + "}}\n no_shadow}\n";
  return text;
}

// Depth of field, focused on look_at. POV-Ray's `aperture` blurs as a lens opening half its
// value across (measured: an edge 9 m behind a plane of focus at 1 m spreads over 0.45·aperture
// at that plane, as a lens of diameter aperture/2 gives), hence 2·aperture_m. Samples per pixel
// adapt between the two blur_samples numbers until the pixel's estimate is stable (confidence,
// variance); POV-Ray places them by a fixed pattern, so pixels repeat across runs and thread
// counts. Final quality stops at a variance of 1/8000 (up to 256 samples): at 1/2000 (up to
// 128) the closeup's blurred street was salted with dark specks, a render's tell (mean
// |pixel − its 5×5 mean| 5.9 % of the level, 3.3 % now, for 2.1× the frame's CPU; BENCHMARKS.md,
// "Focal blur"). Preview takes fewer: grainier discs, the same picture (at least 8: POV-Ray's
// hexagonal grid, below, began with 7 rays; the pigment's sequence adds 4 at a time).
//
// Every pixel shoots its rays through the same points of the lens, so the blurred picture is that
// many sharp copies of the scene laid over each other, and what falls between the copies is
// lost. Without a `bokeh` pigment POV-Ray takes its first 37 points from a hexagonal grid, whose
// rows are level: a thin bright line out of focus came out as a stack of horizontal dashes, the
// closeup's "glitchy noise band" at the roof's far edge, where the lamps' reflections are
// squeezed into slivers. The bokeh pigment, the lens's round opening, makes POV-Ray draw the
// points from a sub-random sequence instead, each at its own height, for the same CPU. And a
// pixel whose first samples all miss a faint sliver stops there, black, as if the sliver were
// not there. A line 1 pixel thin, 51 pixels out of focus, kept 48 % of its light with a third
// of its middle rows dark on the grid at 32 samples, 60 % and one row dark with the pigment, and
// 83 % and none at 64 (`PovRayFocalBlur.AThinLineOutOfFocusSpreadsOverTheOpeningAndKeepsItsLight`),
// for 1.27× the closeup's CPU (BENCHMARKS.md, "Focal blur's rows of dashes"). At 16 the copies
// showed as blotches with jagged edges even without slivers (BENCHMARKS.md, "Focal blur's least
// samples").
std::string focal_blur_text(const ExportParams& look) {
  if (!traces_focal_blur(look)) return {};
  const bool preview = look.quality == Quality::preview;
  return " aperture " + format_number(2.0 * look.aperture_m) + " blur_samples " +
         (preview ? "8,16" : "64,256") + " focal_point " + format_vector(look.camera.look_at) +
         " confidence 0.95 variance " + (preview ? "1/2000" : "1/8000") +
         // The pigment on the unit square: 1 inside the disc of radius 0.5 around its centre. Not
         // a function pattern: with one, POV-Ray 3.7.0.10 crashes on exit (signal 11) after
         // writing the picture.
         " bokeh{pigment{cylindrical rotate 90*x scale 0.5 translate <0.5,0.5,0>"
         " color_map{[0 rgb 0][0.001 rgb 1]}}}";
}

// The environment plate in scene.inc: decides per frame whether to draw it, then includes the
// environment (lights only when the plate stands in for its surfaces) and the plate itself, a
// rectangle filling the camera's view at RT_PlateDistance so each pixel's ray meets the centre
// of the plate's matching pixel. Falls back to the full environment when the plate is missing
// or of another size (rendered by hand at another resolution), during lightning (the flash
// lights the scenery; bolts pass behind buildings) and when rendering the plate itself.
// aspect: the camera's right/up, as written in its camera statement; RT_CameraPosition is
// declared before this text.
std::string environment_with_plate_text(const ExportParams& look, const std::string& aspect) {
  const std::string plate{kEnvironmentPlate};
  std::string text;
  text += "#ifndef(RT_NoPlate) #declare RT_NoPlate=0; #end\n";
  text += "#ifndef(RT_Bolts) #declare RT_Bolts=0; #end\n";
  text += "#declare RT_LightsOnly=0;\n";
  text += "#if(RT_Preview & !RT_NoPlate & RT_Flash<=0 & !RT_Bolts)\n";
  text += "#if(file_exists(\"" + plate + "\"))\n";
  text += "#declare RT_Plate=pigment{image_map{exr \"" + plate + "\" once}}\n";
  text +=
      "#declare RT_LightsOnly=(max_extent(RT_Plate).x=image_width & "
      "max_extent(RT_Plate).y=image_height);\n#end\n#end\n";
  text += "#include \"" + std::string{kEnvironmentInclude} + "\"\n";
  text += "#if(RT_LightsOnly)\n";
  // Far beyond any rain or bolt, so everything the frame adds stands in front of it.
  text += "#declare RT_PlateDistance=10000;\n";
  text += "#declare RT_PlateDir=vnormalize(" + format_vector(look.camera.look_at) +
          "-RT_CameraPosition);\n";
  // POV-Ray's own look_at basis: right = sky × direction, up = direction × right.
  text += "#declare RT_PlateRight=vnormalize(vcross(y,RT_PlateDir));\n";
  text += "#declare RT_PlateUp=vcross(RT_PlateDir,RT_PlateRight);\n";
  text += "#declare RT_PlateWidth=2*RT_PlateDistance*tan(radians(" +
          format_number(look.camera.fov_deg) + "/2));\n";
  text += "polygon{5,<0,0>,<1,0>,<1,1>,<0,1>,<0,0>\n";
  // Emission 1 and nothing else: the plate's pixels come out as they went in.
  // (Checked: an EXR plate's 0.18 and 8 come out of a +FE frame as 0.18 and 8.)
  text += " texture{pigment{RT_Plate} finish{ambient 0 diffuse 0 emission 1}}\n";
  text += " no_shadow no_reflection\n";
  text += " translate<-0.5,-0.5,0> scale<RT_PlateWidth,RT_PlateWidth/" + aspect +
          ",1> translate<0,0,RT_PlateDistance>\n";
  text +=
      " matrix<RT_PlateRight.x,RT_PlateRight.y,RT_PlateRight.z,RT_PlateUp.x,RT_PlateUp.y,"
      "RT_PlateUp.z,RT_PlateDir.x,RT_PlateDir.y,RT_PlateDir.z,0,0,0>\n translate "
      "RT_CameraPosition}\n";
  text += "#end\n";
  return text;
}

// The lightning channel's look, called by the frames for each group of bolt segments (the main
// channel, the branches of one generation) with its brightness B (~0..1, sim::Bolt). Scene-
// linear for an HDR frame: the channel itself (600·B), and around it the light the rain and
// cloud scatter out of it, 2·B at its centre falling off as exp(−(2.5·b/R)²) with the distance
// b from the axis, R the glow cylinder's radius. The glow is drawn on the surface of that
// cylinder: POV-Ray's aoi pattern gives the angle between ray and surface, and sin(aoi) is b/R
// (v = 1 − asin(b/R)/π entering, asin(b/R)/π leaving, hence the symmetric map); each of the two
// surfaces a ray crosses adds half. 0.1 % opaque, it dims the sky behind by that and emits
// 1/1000 of its emission.
//
// Why 600: a return stroke radiates about 870 J per metre of channel (Krider, Dawson and Uman
// 1968, 0.4–1.1 µm). Over a 1/50 s exposure, 300 m of it seen from 500 m through heavy rain
// (37 % transmitted) then brings the camera some tens of times the light of a street lamp 20 m
// away. At 60·B the thunderstorm's bolt added 0.15 of the light of everything else in its frame,
// a white line that lit nothing; at 600·B, 1.4 times everything else (BENCHMARKS.md), its glare
// (the camera's bloom) glows around it and the wet road mirrors it. Both blind viewers chose it
// (4/10 against 3/10 each): "the bolt lights up the fog around it and is faintly reflected in
// the wet road". The estimate would allow brighter still. 600 is per unit of a 0.6 m trunk's
// surface (kBoltLightTrunkRadius_m, frame_values.h): frames scale B for any other trunk radius so
// that the light per metre stays.
// Mirrors see the channel blurred (RT_BoltMirrored, drawn by the frames): RT_BoltBlur times as
// wide and as many times fainter, the same light per metre, where the camera sees it sharp.
// Rain-rippled water is a mirror of countless facets tilted a few degrees: a channel
// 1.2 m across, 600·B bright, is caught by a few of them, each at full brightness, and the
// road mirrored it as "a field of uniform circular dots… like a particle effect"; wider and
// fainter it is caught by more facets, each fainter, and reads as "a continuous streak,
// stretched sideways by ripples" (both viewers of a blind pair chose it, 2026-12-07), as the
// streetlights' lenses are blurred for mirrors (night_street's RT_LensBlur, also 4).
// RT_BoltBlur 0: mirrors see the channel as the camera does.
std::string bolt_macros_text() {
  return "#macro RT_BoltCore(B)\n"
         " texture{pigment{rgb<0.86,0.9,1>} finish{ambient 0 diffuse 0 emission 600*B}}\n#end\n"
         "#macro RT_BoltGlow(B)\n"
         " texture{pigment{aoi color_map{[0 rgbt<1,1,1,0.999>] [0.0641 rgbt<0.7788,0.7788,"
         "0.7788,0.999>]\n  [0.131 rgbt<0.3679,0.3679,0.3679,0.999>] [0.2048 rgbt<0.1054,0.1054,"
         "0.1054,0.999>]\n  [0.2952 rgbt<0.0183,0.0183,0.0183,0.999>] [0.5 rgbt<0,0,0,0.999>]\n"
         "  [0.7048 rgbt<0.0183,0.0183,0.0183,0.999>] [0.7952 rgbt<0.1054,0.1054,0.1054,0.999>]\n"
         "  [0.869 rgbt<0.3679,0.3679,0.3679,0.999>] [0.9359 rgbt<0.7788,0.7788,0.7788,0.999>]\n"
         "  [1 rgbt<1,1,1,0.999>]}}\n"
         "  finish{ambient 0 diffuse 0 emission 1000*B*<0.8,0.85,1>}}\n#end\n"
         "#ifndef(RT_BoltBlur) #declare RT_BoltBlur=4; #end\n"
         "#macro RT_BoltMirrored(A,E,R,B)\n"
         " cylinder{A,E,R*RT_BoltBlur RT_BoltCore(B/RT_BoltBlur)}\n#end\n";
}

}  // namespace

bool environment_plate_applies(const ExportParams& look) {
  const bool scenery_beyond_rain =
      look.environment.include_path.empty() &&
      (look.environment.name == "night_street" || look.environment.name == "field");
  // Ground fog is densest at the ground: its density there bounds what a drop misses.
  const double fog_density = look.fog.mode == FogMode::off ? 0.0 : look.fog.density_per_m;
  const bool thin_fog = 1.0 - std::exp(-fog_density * look.rain.far_m) <= kPlateFogDimming;
  // The plate is the camera's picture, already through the lens barrel's rim: a frame's rays
  // to it would pass the rim a second time.
  const bool barrel = look.optical_vignetting > 0.0;
  return look.quality == Quality::preview && look.environment_plate && scenery_beyond_rain &&
         thin_fog && !barrel;
}

std::string plate_pov_text() {
  return "// raintrace: the environment alone, without rain: plate.ini renders it into\n"
         "// textures/environment_plate.exr, which the frames of a preview draw behind the rain.\n"
         "#version 3.7;\n#declare RT_NoPlate=1;\n#include \"scene.inc\"\n";
}

std::string plate_ini_text(const ExportParams& look) {
  validate(look);
  std::string text;
  text +=
      "; raintrace: `povray plate.ini` renders the environment once, without rain, into\n"
      "; textures/environment_plate.exr. Render it before scene.ini: every frame then draws this\n"
      "; picture behind the rain instead of ray tracing the environment again. Without it the\n"
      "; frames trace the whole environment themselves (the same scene, only slower).\n";
  text += std::string{"Input_File_Name="} + kPlatePov + "\n";
  text += std::string{"Output_File_Name="} + kEnvironmentPlate + "\n";
  text += "Output_File_Type=E\nOutput_Alpha=off\n";
  text += "Width=" + std::to_string(look.width) + "\nHeight=" + std::to_string(look.height) + "\n";
  text += "Library_Path=.\nQuality=9\nAntialias=off\nDisplay=off\nPause_When_Done=off\n";
  return text;
}

std::string scene_inc_text(const ExportParams& look) {
  validate(look);
  const std::string aspect = format_number(static_cast<double>(look.width) / look.height);
  std::string text;
  text +=
      "// raintrace scene.inc: camera, lights, environment and materials shared by every frame.\n"
      "// Each frames/frame_NNNN.pov declares RT_Flash and RT_FlashPosition, then includes this.\n"
      "#version 3.7;\n"
      "#ifndef(RT_Mask) #declare RT_Mask=0; #end\n"
      "#ifndef(RT_Flash) #declare RT_Flash=0; #end\n"
      "#ifndef(RT_FlashPosition) #declare RT_FlashPosition=<0,300,200>; #end\n";
  // Environments (built-in or the user's) read RT_Preview to pick cheaper stand-ins for slow
  // effects at quality "preview". Guarded like the others so `Declare=RT_Preview=0` on the
  // command line renders an exported preview folder with the final look, and vice versa.
  text += std::string{"#ifndef(RT_Preview) #declare RT_Preview="} +
          (look.quality == Quality::preview ? "1" : "0") + "; #end\n";
  // Overlapping transparent streaks and refraction in drops each cost a trace level; too few
  // levels leave black specks where rain is dense.
  text += "global_settings{assumed_gamma 1.0 max_trace_level 32 adc_bailout 0.004}\n";
  text += "camera{perspective location " + format_vector(look.camera.position) + " look_at " +
          format_vector(look.camera.look_at) + " right x*" + aspect + " up y angle " +
          format_number(look.camera.fov_deg) + focal_blur_text(look) + "}\n";
  text += "#declare RT_LightningLight=" + format_number(look.lightning_light) + ";\n";
  text += bolt_macros_text();
  text += "#declare RT_CameraPosition=" + format_vector(look.camera.position) + ";\n";
  text += "#ifndef(RT_LightsOnly) #declare RT_LightsOnly=0; #end\n";
  text += "#if(RT_Mask)\nbackground{rgb 0}\n#else\n";
  text += lens_barrel_text(look);
  text += "#declare RT_KeyLight=1;\n";
  if (look.fog.mode == FogMode::media && look.fog.density_per_m > 0.0) {
    // Media mist scatters the lamps' light to the side itself, so night_street paints no cones.
    // Its droplets' forward lobes (the aureole and the diffraction halo around each lamp) are
    // too narrow for eight samples a ray to find: the environment paints those for the mist's
    // scattering coefficient, tinted as the medium's. Without them, heavy_fog's lamps hung in
    // the fog with no halo, and both blind viewers of a pair chose them painted.
    const glm::dvec3 tint = glm::clamp(look.fog.colour, 0.0, 1.0);
    const double scattering = kMediaScatteringShare * look.fog.density_per_m;
    text += "#declare RT_LampHaze=" + format_number(scattering * (tint.x + tint.y + tint.z) / 3.0) +
            ";\n#declare RT_LampCones=0;\n";
    // And its extinction within its sphere, for what the environment draws nearer the camera
    // than the light it stands for (night_street's sign halos).
    text += "#declare RT_MediaExtinction=" + format_number(look.fog.density_per_m) +
            ";\n#declare RT_MediaDepth=" + format_number(look.fog.depth_m) + ";\n";
  }
  if (look.fog.mode == FogMode::ground && look.fog.density_per_m > 0.0) {
    // The environment's painted lamp haze is this mist where it stands around the lamps.
    text += "#declare RT_GroundFogDensity=" + format_number(look.fog.density_per_m) + ";\n";
    text += "#declare RT_GroundFogDepth=" + format_number(look.fog.depth_m) + ";\n";
  }
  text += ground_scene_text(look);
  // The rain medium's extinction and macros come before the environment, which may draw the
  // rain's scattering around its lights itself (night_street's lamp glows read
  // RT_RainExtinction); the medium is placed after it.
  const std::string medium = rain_medium_text(look);
  text += medium;
  const bool plate = environment_plate_applies(look);
  if (plate) {
    text += environment_with_plate_text(look, aspect);
  } else {
    text += "#include \"" + std::string{kEnvironmentInclude} + "\"\n";
  }
  // The light of the surroundings that a drop refracts (docs/rain-appearance.md): declared by
  // the environment; without it the rain shows only the lights it scatters.
  text += "#ifndef(RT_RainSurround) #declare RT_RainSurround=rgb 0; #end\n";
  // The plate holds the fog as it holds the rain medium: frames that draw it leave it out,
  // or its light would be counted twice on the way to the plate.
  const std::string fog = fog_text(look.fog, look.camera);
  text += plate && !fog.empty() ? "#if(!RT_LightsOnly)\n" + fog + "#end\n" : fog;
  // The rain medium holds no simulated drop, so the environment plate may hold it exactly:
  // frames that draw the plate leave it out and pay nothing. Elsewhere a preview draws its fog
  // form (free, without the lights' scattering, 75 % of the medium's effect on the default
  // street) and final the media (+0.6 CPU s a 640×360 frame), unless the environment declares
  // RT_RainAsFog 1: that its glows draw the light the medium would scatter, so the fog form is
  // all the medium adds (the default's final frame: 8 % less POV-Ray time, the picture 0.3 %
  // of its mean luma away). Guarded in POV-Ray, so Declare=RT_Preview=0 still renders a
  // preview folder as the final scene.
  if (!medium.empty()) {
    text += plate ? "#if(!RT_LightsOnly)\nRT_RainMedium()\n#end\n"
                  : "#ifndef(RT_RainAsFog) #declare RT_RainAsFog=0; #end\n"
                    "#if(RT_Preview | RT_RainAsFog)\nRT_RainFog()\n#else\nRT_RainMedium()\n#end\n";
  }
  // The flash lights the whole scene from the bolt's top; RT_KeyLight comes from the
  // environment, so lightning_light is relative to its main light.
  text +=
      "#if(RT_Flash>0)\nlight_source{RT_FlashPosition color rgb "
      "RT_Flash*RT_LightningLight*RT_KeyLight*<0.85,0.88,1>}\n#end\n#end\n";
  // After the environment, which may declare RT_RainSurround for the materials.
  text += drop_lobes_text();
  text += "#include \"" + std::string{kMaterialsInclude} + "\"\n";
  return text;
}

std::string dispatcher_text(const char* prefix, int digits) {
  const std::string p{prefix};
  if (p != "frame" && p != "mask") throw std::invalid_argument("dispatcher prefix: " + p);
  return "// raintrace: the animation's scene. POV-Ray sets frame_number from scene.ini's frame\n"
         "// range; this picks that frame's file. Paths are relative to the folder (+L.).\n"
         "#version 3.7;\n#include concat(\"frames/" +
         p + "_\", str(frame_number, -" + std::to_string(digits) + ", 0), \".pov\")\n";
}

std::string ini_text(const ExportParams& look, int frame_count, const char* prefix,
                     const char* dispatcher, FrameSubset frames) {
  validate(look);
  const std::string p{prefix};
  const std::string d{dispatcher};
  if ((p != "frame" || d != "scene.pov") && (p != "mask" || d != "mask.pov")) {
    throw std::invalid_argument("ini_text: unknown prefix/dispatcher " + p + "/" + d);
  }
  if (frame_count < 1) throw std::invalid_argument("ini_text: frame_count must be >= 1");
  if (frames.first < 1 || frames.last < frames.first || frames.last > frame_count) {
    throw std::invalid_argument("ini_text: frames " + std::to_string(frames.first) + "-" +
                                std::to_string(frames.last) + " are not in 1-" +
                                std::to_string(frame_count));
  }
  const int digits = frame_digits(frame_count);
  const std::string last_frame(static_cast<std::size_t>(digits), '9');
  // Focal blur already shoots up to 128 rays through each pixel; antialiasing on top would
  // multiply them again for edges the blur has already softened (POV-Ray's own advice).
  const bool antialias = look.quality == Quality::final && p == "frame" && !traces_focal_blur(look);
  std::string text;
  text += "; raintrace: run `povray " + std::string{p == "frame" ? "scene" : "mask"} +
          ".ini` inside this folder to render the animation.\n";
  text +=
      "; POV-Ray pads the frame number in output names to the digit count of Final_Frame\n"
      "; (48 frames would give images/frame_01.png). Final_Frame is therefore all nines, as\n"
      "; many digits as the frame files, and Subset_Start_Frame/Subset_End_Frame pick the\n"
      "; frames that exist: frame_number and the image names then match frames/*_NNNN.pov.\n"
      "; raintrace never uses `clock`, so the stretched clock range is harmless.\n"
      "; One range only: povray scene.ini +SF5 +EF9\n";
  if (p == "frame" && environment_plate_applies(look)) {
    text += "; Preview: `povray plate.ini` first renders the environment once for all frames.\n";
  }
  if (p == "frame") {
    // The develop settings are not written here: changing them must not change any file POV-Ray
    // reads, or every frame would count as changed and be rendered again.
    text +=
        "; Frames are scene-linear half-float OpenEXR (images/frame_NNNN.exr), the camera's raw\n"
        "; light. `raintrace render .` in this folder develops them into images/frame_NNNN.png\n"
        "; (exposure, Filmic, bloom, grain, vignetting: the scene's [camera] keys); by hand, the\n"
        "; Filmic view and look alone at exposure_ev 0 (docs/hdr-pipeline.md) are:\n"
        ";   oiiotool images/frame_0001.exr --colorconfig "
        "/usr/share/blender/datafiles/colormanagement/config.ocio\n"
        ";     --ociolook:from=Linear:to=Linear \"Medium High Contrast\" --ociodisplay:from=Linear "
        "sRGB Filmic\n"
        ";     -d uint8 -o frame_0001.png\n";
  }
  text += "Input_File_Name=" + d + "\n";
  text += "Output_File_Name=images/" + p + "_\n";
  text += std::string{"Output_File_Type="} + (p == "frame" ? "E" : "N") + "\nOutput_Alpha=off\n";
  text += "Width=" + std::to_string(look.width) + "\nHeight=" + std::to_string(look.height) + "\n";
  text += "Library_Path=.\n";
  text += "Initial_Frame=1\nFinal_Frame=" + last_frame + "\n";
  text += "Subset_Start_Frame=" + std::to_string(frames.first) +
          "\nSubset_End_Frame=" + std::to_string(frames.last) + "\n";
  text += "Cyclic_Animation=off\n";
  // Quality 9 in both modes: lower levels drop refraction (5) or media (8), which are the rain.
  text += "Quality=9\n";
  if (antialias) {
    // Adaptive antialiasing without jitter: repeatable renders across runs and thread counts.
    // A pixel that differs from its neighbours by more than 0.15 is traced again as 2×2
    // samples, not 3×3 at 0.2: the night street's 1280×720 frame in 0.8× the POV-Ray time,
    // which the 150 frames/hour floor needs, and side by side blind viewers saw no difference
    // (BENCHMARKS.md, "Antialiasing at final quality", "The road's aggregate at its stones'
    // size" and "2×2 antialiasing at threshold 0.15").
    text +=
        "Antialias=on\nSampling_Method=1\nAntialias_Threshold=0.15\nAntialias_Depth=2\n"
        "Jitter=off\n";
  } else {
    text += "Antialias=off\n";
  }
  text += "Display=off\nPause_When_Done=off\n";
  return text;
}

}  // namespace raintrace::povgen
