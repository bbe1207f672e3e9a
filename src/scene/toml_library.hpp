#pragma once
// toml++, as every file of the scene module includes it. Its own assertions are off in every build,
// as they are in Release: some fire on malformed input that its parser then reports as an error (a
// table header "[" that ends its line: tests/fuzz/regressions/scene_text), and a scene file is the
// user's to get wrong. So the fuzzers, built in Debug, test what users run.
#ifndef TOML_ASSERT
#define TOML_ASSERT(expr) static_assert(true)
#endif
#include <toml++/toml.h>
