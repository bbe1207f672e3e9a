// SPDX-License-Identifier: MIT
// collide_bad_scene_files DIR: writes the scene file of each bad-input matrix case that has one
// (tests/app/bad_input_cases.cpp) to DIR/NAME.toml, for the schema test to check.
#include <fstream>
#include <iostream>

#include "bad_input_cases.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: collide_bad_scene_files DIR\n";
    return 2;
  }
  for (const collide::bad_input::BadInput& c : collide::bad_input::cases()) {
    if (c.scene_text.empty()) continue;
    std::ofstream(std::string(argv[1]) + "/" + c.name + ".toml", std::ios::binary) << c.scene_text;
  }
  return 0;
}
