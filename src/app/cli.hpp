#pragma once
#include <iosfwd>

namespace collide::app {

// kParseOnly stops after the command line is parsed: no command runs, so nothing is read or
// written (the argv fuzzer; --help and --version still print to `out`).
enum class CliMode { kRun, kParseOnly };

// Parses the command line, runs the command and returns the process exit code (0 success,
// 1 runtime failure, 2 bad usage or input). Results go to `out`, messages to `err`.
int runCli(int argc, const char* const* argv, std::ostream& out, std::ostream& err,
           CliMode mode = CliMode::kRun);

}  // namespace collide::app
