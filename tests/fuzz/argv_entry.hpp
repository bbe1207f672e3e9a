#pragma once
// The argv fuzzer's entry (issue 14), shared by the libFuzzer harness and the regression test that
// replays saved inputs in every build. Separate from fuzz_entries because it needs the whole
// command line (collide_app), not only the scene library.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace collide::fuzz {

// The input split at NUL bytes into the arguments after `collide` (at most 64).
std::vector<std::string> argvFromBytes(const std::uint8_t* data, std::size_t size);

// The arguments through the command-line parser only (app::CliMode::kParseOnly): no command
// runs, so nothing is read, rendered or written whatever the arguments name. Any input must
// end in exit 0 (parsed, or --help/--version) or exit 2 with exactly one line on stderr,
// "collide: ..." without control characters and of bounded length, and nothing on stdout.
void fuzzCommandLine(const std::uint8_t* data, std::size_t size);

}  // namespace collide::fuzz
