#pragma once
// Runs the command line in-process, as `collide ARGS...`, capturing what it prints.
#include <string>
#include <vector>

namespace collide::test {

struct CliResult {
  int exit_code;
  std::string out, err;  // stdout and stderr
};

CliResult run(std::vector<std::string> args);

}  // namespace collide::test
