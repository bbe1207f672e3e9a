// libFuzzer harness: the command line, parsed only (nothing runs, nothing is written). Each input
// is the arguments after `collide`, separated by NUL bytes. Build with scripts/check-fuzz.
#include "argv_entry.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  collide::fuzz::fuzzCommandLine(data, size);
  return 0;
}
