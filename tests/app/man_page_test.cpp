// The roff escaping of collide(1): text from --help must reach man(1) as text, never as requests,
// and options must read (and copy) as ASCII hyphen-minus.
#include "app/man_page.hpp"

#include <gtest/gtest.h>

namespace collide::app {
namespace {

TEST(RoffEscapeTest, HyphensBecomeMinusSigns) {
  EXPECT_EQ(roffEscape("--set body.2.mass=3"), "\\-\\-set body.2.mass=3");
}

TEST(RoffEscapeTest, BackslashesArePrintedNotInterpreted) {
  EXPECT_EQ(roffEscape("C:\\fonts\\a.ttf"), "C:\\efonts\\ea.ttf");
}

TEST(RoffEscapeTest, ALineStartingWithAControlCharacterStaysText) {
  EXPECT_EQ(roffEscape(".toml files"), "\\&.toml files");
  EXPECT_EQ(roffEscape("'quoted'"), "\\&'quoted'");
  EXPECT_EQ(roffEscape("a\n.b\nc.d"), "a\n\\&.b\nc.d");
}

TEST(RoffEscapeTest, PlainTextIsUnchanged) {
  EXPECT_EQ(roffEscape("Render one instant"), "Render one instant");
}

}  // namespace
}  // namespace collide::app
