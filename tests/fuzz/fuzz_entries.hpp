#pragma once
// What the fuzzers exercise, shared by the libFuzzer harnesses and the regression test that replays
// every saved input in a normal build. Each entry must never crash, hang or leak for any input:
// bad input ends in a SceneError (a one-line message), never anything else.
#include <cstddef>
#include <cstdint>

namespace collide::fuzz {

// Scene text through the loader and validator; a scene that loads must write back as TOML that
// loads again.
void fuzzSceneText(const std::uint8_t* data, std::size_t size);

// `--set` expressions applied to a built-in preset, one per line of the input.
void fuzzSetExpressions(const std::uint8_t* data, std::size_t size);

}  // namespace collide::fuzz
