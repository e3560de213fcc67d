// The scene.ini / dispatcher mirror what the exporter writes: Final_Frame=9999 so POV-Ray names
// images with 4 digits, and scene.pov includes frames/frame_NNNN.pov by frame_number.
#include "render/test_folder.h"

#include <fmt/core.h>
#include <unistd.h>
#include <cstdlib>
#include <fstream>

#include "output/layout.h"
#include "output/manifest.h"
#include "output/test_dir.h"
#include "povgen/content_hash.h"
#include "render/povray_command.h"
#include "render/process.h"
#include "render/text_file.h"

namespace raintrace::render::testing {
namespace {

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out{path, std::ios::binary};
  out << text;
}

std::string frame_text(int frame, int spheres) {
  std::string s = "#include \"scene.inc\"\nunion {\n";
  for (int k = 0; k < spheres; ++k) {
    // A fixed pseudo-random cloud that moves with the frame number.
    const double x = ((k * 37) % 100) / 25.0 - 2.0 + 0.05 * frame;
    const double y = ((k * 53) % 80) / 25.0 - 1.6;
    const double z = ((k * 71) % 60) / 20.0;
    s += fmt::format("  sphere {{ <{},{},{}>, 0.04 }}\n", x, y, z);
  }
  s += fmt::format("  pigment {{ rgb <0.2,{},0.9> }}\n}}\n", 0.1 + 0.8 * (frame % 10) / 10.0);
  return s;
}

// The preview exporter's plate files in miniature: the environment (a sky and a lit floor) once
// into the plate, and a scene.inc that puts the plate on a screen filling the view.
void write_plate_files(const std::filesystem::path& dir, const TestFolderSpec& spec) {
  write_file(dir / "plate.ini", fmt::format("Input_File_Name=plate.pov\nWidth={}\nHeight={}\n"
                                            "Output_File_Name=textures/environment_plate.exr\n"
                                            "Output_File_Type=E\nAntialias=off\nQuality=9\n"
                                            "Library_Path=.\n",
                                            spec.width, spec.height));
  write_file(dir / "plate.pov",
             "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
             "camera { location <0,0,-5> look_at <0,0,0> }\n"
             "light_source { <5,5,-5> rgb 1 }\n#include \"environment.inc\"\n");
  write_file(dir / "environment.inc",
             "sky_sphere { pigment { gradient y color_map { [0 rgb <0.6,0.7,0.9>] "
             "[1 rgb <0.1,0.2,0.5>] } } }\n"
             "plane { y, -1.5 pigment { checker rgb 0.2 rgb 0.8 } }\n");
  // The default camera sees ±10 × ±7.5 units at the screen's distance of 15.
  write_file(
      dir / "scene.inc",
      read_text(dir / "scene.inc") +
          fmt::format("#declare RT_PlateUsed = false;\n"
                      "#if (!RT_Mask & file_exists(\"textures/environment_plate.exr\"))\n"
                      "  #declare RT_Plate = pigment {{ image_map {{ exr "
                      "\"textures/environment_plate.exr\" }} }};\n"
                      "  #declare RT_PlateSize = max_extent(RT_Plate);\n"
                      "  #declare RT_PlateUsed = (RT_PlateSize.x = {} & RT_PlateSize.y = {});\n"
                      "#end\n"
                      "#if (RT_PlateUsed)\n"
                      "  #debug \"raintrace: environment plate used\\n\"\n"
                      "  box {{ <-0.5,-0.5,0>, <0.5,0.5,0.001> pigment {{ RT_Plate "
                      "translate <-0.5,-0.5,0> }}\n"
                      "    finish {{ emission 1 diffuse 0 }} no_shadow scale <20,15,1> "
                      "translate z*10 }}\n"
                      "#else\n"
                      "  #debug \"raintrace: full environment\\n\"\n"
                      "  #include \"environment.inc\"\n"
                      "#end\n",
                      spec.width, spec.height));
}

}  // namespace

void write_test_folder(const std::filesystem::path& dir, const TestFolderSpec& spec) {
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "frames");
  write_file(dir / "scene.ini", fmt::format("Input_File_Name=scene.pov\nInitial_Frame=1\n"
                                            "Final_Frame=9999\nInitial_Clock=0\nFinal_Clock=1\n"
                                            "Width={}\nHeight={}\nAntialias=off\nQuality=5\n",
                                            spec.width, spec.height));
  write_file(dir / "scene.pov",
             "#version 3.7;\n#include concat(\"frames/frame_\", str(frame_number, -4, 0), "
             "\".pov\")\n");
  write_file(dir / "mask.ini", fmt::format("Input_File_Name=mask.pov\nInitial_Frame=1\n"
                                           "Final_Frame=9999\nWidth={}\nHeight={}\n"
                                           "Antialias=off\n",
                                           spec.width, spec.height));
  write_file(dir / "mask.pov",
             "#version 3.7;\n#include concat(\"frames/mask_\", str(frame_number, -4, 0), "
             "\".pov\")\n");
  write_file(dir / "scene.inc",
             "global_settings { assumed_gamma 1.0 }\n"
             "camera { location <0,0,-5> look_at <0,0,0> }\n"
             "light_source { <5,5,-5> rgb 1 }\nbackground { rgb 0.05 }\n"
             "#ifndef (RT_Mask) #declare RT_Mask = 0; #end\n"
             "#if (RT_Mask) #default { finish { ambient 1 diffuse 0 } } #end\n");
  if (spec.plate) write_plate_files(dir, spec);
  output::Manifest manifest;
  manifest.raintrace_version = "test";
  manifest.identity.width = spec.width;
  manifest.identity.height = spec.height;
  manifest.identity.fps = 24;
  manifest.identity.masks = spec.masks;
  manifest.frame_count = spec.frames;
  for (int f = 1; f <= spec.frames; ++f) {
    const std::string text = frame_text(f, spec.spheres);
    output::FrameEntry entry;
    entry.number = f;
    entry.image.scene = output::frame_scene_name(output::Pass::image, f);
    entry.image.path = output::final_image_name(output::Pass::image, f);
    entry.developed.path = output::developed_image_name(f);
    entry.input_hash = povgen::content_hash(text);
    write_file(dir / entry.image.scene, text);
    if (spec.masks) {
      output::PictureRecord mask;
      mask.scene = output::frame_scene_name(output::Pass::mask, f);
      mask.path = output::final_image_name(output::Pass::mask, f);
      write_file(dir / mask.scene,
                 fmt::format("#declare RT_Mask = 1;\n#include \"frames/frame_{:04d}.pov\"\n", f));
      entry.mask = mask;
    }
    manifest.frames.push_back(entry);
  }
  output::write_manifest(dir / output::kManifest, manifest);
}

void replace_frame(const std::filesystem::path& dir, int frame, const std::string& text) {
  auto manifest = output::read_manifest(dir / output::kManifest);
  for (auto& entry : manifest.frames) {
    if (entry.number != frame) continue;
    write_file(dir / entry.image.scene, text);
    entry.input_hash = povgen::content_hash(text);
  }
  output::write_manifest(dir / output::kManifest, manifest);
}

std::filesystem::path fresh_test_dir(const std::string& name) {
  return output::testing::fresh_test_dir("render_" + name);
}

bool system_has_povray() { return find_program("povray").has_value(); }

std::filesystem::path povray_that_does_not_start(const std::filesystem::path& dir,
                                                 const std::string& ini, int failures) {
  const auto real_povray = find_program("povray");
  EXPECT_TRUE(real_povray.has_value());
  const auto bin = dir / "fake_bin";
  std::filesystem::create_directories(bin);
  const std::string starts = (dir / "starts").string();
  std::ofstream{bin / "povray"} << fmt::format(
      "#!/bin/sh\n"
      "if [ \"$1\" = '{0}' ]; then\n"
      "  n=$(( $(cat '{1}' 2>/dev/null || echo 0) + 1 )); echo $n > '{1}'\n"
      "  if [ $n -le {2} ]; then echo '{3}' >&2; exit 1; fi\n"
      "fi\n"
      "exec '{4}' \"$@\"\n",
      ini, starts, failures, kPovrayStartupTimeout, real_povray.value_or("povray").string());
  std::filesystem::permissions(bin / "povray", std::filesystem::perms::owner_all,
                               std::filesystem::perm_options::add);
  return bin;
}

std::map<std::string, std::string> path_with(const std::filesystem::path& bin) {
  const char* path = std::getenv("PATH");
  return {{"PATH", bin.string() + ":" + (path != nullptr ? path : "/usr/bin:/bin")}};
}

}  // namespace raintrace::render::testing
