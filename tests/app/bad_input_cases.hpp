#pragma once
// The bad-input matrix's cases (bad_input_cases.cpp): what a user types, and what the one
// stderr line must name.
#include <string>
#include <vector>

namespace collide::bad_input {

struct BadInput {
  const char* name;
  std::string scene_text;            // written to scene.toml when not empty
  std::string arguments;             // after `collide`; {dir} is replaced by the scratch directory
  std::vector<std::string> needles;  // each must appear in the one stderr line
  // A shell command run first in the scratch directory; exit 77 skips the case (e.g. mknod
  // refused).
  std::string prepare = "";
};

// Every case, each with a unique name (the test's parameter name).
const std::vector<BadInput>& cases();

}  // namespace collide::bad_input
