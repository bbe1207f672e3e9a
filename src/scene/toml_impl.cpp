// The one translation unit that compiles toml++ (the library is built with TOML_HEADER_ONLY=0,
// so the other files only see declarations and build faster).
#define TOML_IMPLEMENTATION
#include "scene/toml_library.hpp"
