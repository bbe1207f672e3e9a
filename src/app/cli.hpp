#pragma once
#include <iosfwd>

namespace collide::app {

// Parses the command line, runs the command and returns the process exit code (0 success,
// 1 runtime failure, 2 bad usage or input). Results go to `out`, messages to `err`.
int runCli(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace collide::app
