// SPDX-License-Identifier: MIT
#include "progress_lines.hpp"

#include <sstream>

namespace collide::test {

std::string withoutProgressLines(const std::string& err) {
  std::istringstream lines(err);
  std::string kept, line;
  while (std::getline(lines, line)) {
    const bool progress = line.rfind("simulating: ", 0) == 0 || line.rfind("rendering: ", 0) == 0;
    if (!progress) kept += line + "\n";
  }
  return kept;
}

}  // namespace collide::test
