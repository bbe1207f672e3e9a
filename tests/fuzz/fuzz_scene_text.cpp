// libFuzzer harness: scene files. Build with scripts/check-fuzz.
#include "fuzz_entries.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  collide::fuzz::fuzzSceneText(data, size);
  return 0;
}
