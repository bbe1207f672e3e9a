#include "core/error.hpp"

#include <cstdio>
#include <cstdlib>

namespace collide::core {

void assertionFailed(const char* function, const std::string& message) {
  std::fprintf(stderr, "%s: assertion failed: %s\n", function, message.c_str());
  std::abort();
}

}  // namespace collide::core
