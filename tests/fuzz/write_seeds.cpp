// Writes the fuzzers' seed corpus: every preset as a scene file (DIR/NAME.toml). Built beside the
// harnesses so seeding needs only the scene library, not the whole tool.
#include <cstdio>
#include <fstream>
#include <string>

#include "scene/scene_io.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: write_seeds DIR\n");
    return 2;
  }
  for (const collide::scene::PresetInfo& preset : collide::scene::presetList()) {
    std::ofstream(std::string(argv[1]) + "/" + preset.name + ".toml")
        << collide::scene::presetToml(preset.name);
  }
  return 0;
}
