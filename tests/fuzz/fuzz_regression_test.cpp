// Replays every input the fuzzers once found troublesome (tests/fuzz/regressions/<target>/*), in
// the normal build, so a fixed crash stays fixed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "argv_entry.hpp"
#include "fuzz_entries.hpp"

namespace collide::fuzz {
namespace {
namespace fs = std::filesystem;

std::string readFile(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

template <typename Entry>
int replay(const std::string& target, Entry entry) {
  int count = 0;
  const fs::path dir = fs::path(COLLIDE_FUZZ_REGRESSIONS) / target;
  if (!fs::is_directory(dir)) return 0;
  for (const fs::directory_entry& file : fs::directory_iterator(dir)) {
    const std::string bytes = readFile(file.path());
    SCOPED_TRACE(file.path().string());
    entry(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    ++count;
  }
  return count;
}

TEST(FuzzRegressionTest, SceneTextInputsLoadOrFailCleanly) {
  EXPECT_GT(replay("scene_text", fuzzSceneText), 0);
}

TEST(FuzzRegressionTest, SetExpressionInputsApplyOrFailCleanly) {
  EXPECT_GT(replay("set_expression", fuzzSetExpressions), 0);
}

TEST(FuzzRegressionTest, CommandLinesParseOrFailWithOneLine) {
  EXPECT_GT(replay("argv", fuzzCommandLine), 0);
}

}  // namespace
}  // namespace collide::fuzz
