// update-scene-format: rewrites the generated columns of docs/scene-format.md from the
// parameter tables (see scene_format_doc.h). Run through CMake:
//   cmake --build build --target update-scene-format
#include <cstdio>
#include <exception>
#include <fstream>
#include <sstream>

#include "cli/scene_format_doc.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s docs/scene-format.md\n", argv[0]);
    return 2;
  }
  try {
    std::ifstream in(argv[1], std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) throw std::runtime_error(std::string{"cannot read "} + argv[1]);
    const std::string updated = raintrace::cli::update_scene_format_doc(text.str());
    if (updated == text.str()) {
      std::printf("%s is up to date\n", argv[1]);
      return 0;
    }
    std::ofstream(argv[1], std::ios::binary | std::ios::trunc) << updated;
    std::printf("updated %s: review the change (rows marked TODO need a meaning)\n", argv[1]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "update-scene-format: %s\n", e.what());
    return 1;
  }
  return 0;
}
