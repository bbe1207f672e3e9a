#include "fuzz_entries.hpp"

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "scene/scene_io.hpp"

namespace collide::fuzz {
namespace {

// A finding: print what happened and abort so libFuzzer (or the regression test) records it.
[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz finding: %s\n", what.c_str());
  std::abort();
}

// Bad input must give exactly one line.
void checkMessage(const scene::SceneError& error) {
  const std::string message = error.what();
  if (message.empty()) finding("empty error message");
}

}  // namespace

void fuzzSceneText(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  scene::SceneDesc loaded;
  try {
    loaded = scene::parseSceneText(text, "fuzz.toml");
  } catch (const scene::SceneError& error) {
    checkMessage(error);
    return;
  }
  // Whatever loads must survive a round trip through the writer.
  const std::string written = scene::sceneToToml(loaded);
  try {
    scene::parseSceneText(written, "roundtrip.toml");
  } catch (const scene::SceneError& error) {
    finding(std::string("a loaded scene does not load back: ") + error.what() + "\n" + written);
  }
}

void fuzzSetExpressions(const std::uint8_t* data, std::size_t size) {
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  std::vector<scene::Override> overrides;
  std::string line;
  try {
    while (std::getline(lines, line) && overrides.size() < 16) {
      overrides.push_back(scene::parseSetExpression(line));
    }
    // Two presets: a 1D one and a 2D one, so keys of both kinds are reachable.
    scene::loadScene("worked-example", overrides);
    scene::loadScene("billiards-glancing", overrides);
  } catch (const scene::SceneError& error) {
    checkMessage(error);
  }
}

}  // namespace collide::fuzz
