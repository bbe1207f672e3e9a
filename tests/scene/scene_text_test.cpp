// SPDX-License-Identifier: MIT
// Issue 38: text from a scene goes into terminals, JSON, a batch's protocol, LaTeX, Markdown, SVG
// and PDF, so a scene's strings are refused at load when they hold what any of those would act on
// or refuse: bytes that are not UTF-8, control characters (C0, DEL, C1), the line and paragraph
// separators, and the Unicode non-characters. From a file (raw or as TOML escapes) and from --set.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "scene/scene_io.hpp"

namespace collide::scene {
namespace {

const std::string kBody = "[[body]]\nmass = 1\nsize = 0.5\nposition = 0\n";

// UTF-8 of `code_point` (a test's own encoder: the rule under test decodes).
std::string utf8(char32_t c) {
  std::string out;
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (c >> 18));
    out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
  return out;
}

// "U+001B", as the message names a code point.
std::string named(char32_t c) {
  char text[16];
  std::snprintf(text, sizeof text, "U+%04X", static_cast<unsigned>(c));
  return text;
}

// "\u001B" or "\U0010FFFF": the code point as a TOML escape.
std::string tomlEscape(char32_t c) {
  char text[16];
  if (c <= 0xFFFF) {
    std::snprintf(text, sizeof text, "\\u%04X", static_cast<unsigned>(c));
  } else {
    std::snprintf(text, sizeof text, "\\U%08X", static_cast<unsigned>(c));
  }
  return text;
}

std::string problemOf(const std::string& text, const std::vector<Override>& overrides = {}) {
  try {
    parseSceneText(text, "s.toml", overrides);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

// Every kind the rule names, at both ends of each range.
const std::vector<char32_t> kRefused = {0x01,    0x07,    0x09,    0x0A,     0x0D,    0x1B,
                                        0x1F,    0x7F,    0x80,    0x85,     0x9B,    0x9F,
                                        0x2028,  0x2029,  0xFDD0,  0xFDEF,   0xFFFE,  0xFFFF,
                                        0x1FFFE, 0x1FFFF, 0x8FFFE, 0x10FFFE, 0x10FFFF};

class RefusedCodePointTest : public ::testing::TestWithParam<char32_t> {};

TEST_P(RefusedCodePointTest, InATitleAsATomlEscape) {
  const char32_t c = GetParam();
  const std::string problem = problemOf("title = \"a" + tomlEscape(c) + "b\"\n" + kBody);
  EXPECT_NE(problem.find("s.toml:1:9: title: "), std::string::npos) << problem;
  EXPECT_NE(problem.find("holds " + named(c)), std::string::npos) << problem;
  EXPECT_NE(problem.find("allowed: "), std::string::npos) << problem;
  EXPECT_EQ(problem.find('\n'), std::string::npos) << "one line: " << problem;
}

TEST_P(RefusedCodePointTest, InABodyNameAsRawUtf8) {
  const char32_t c = GetParam();
  if (c == 0x0A || c == 0x0D) GTEST_SKIP() << "a raw line break ends a TOML string";
  const std::string problem = problemOf(kBody + "name = \"x" + utf8(c) + "\"\n");
  if (c < 0x80 && c != 0x09) {
    // TOML itself allows no raw control but the tab in a string: refused as malformed.
    EXPECT_NE(problem.find("s.toml:5:"), std::string::npos) << problem;
    return;
  }
  EXPECT_NE(problem.find("body.1.name: "), std::string::npos) << problem;
  EXPECT_NE(problem.find("holds " + named(c)), std::string::npos) << problem;
}

TEST_P(RefusedCodePointTest, ThroughSetAsABareWord) {
  const char32_t c = GetParam();
  const std::string problem = problemOf(kBody, {parseSetExpression("title=x" + utf8(c) + "y")});
  EXPECT_NE(problem.find("title"), std::string::npos) << problem;
  // A line feed makes no TOML value and no bare word: refused as such.
  if (c != 0x0A) {
    EXPECT_NE(problem.find("holds " + named(c)), std::string::npos) << problem;
  }
}

INSTANTIATE_TEST_SUITE_P(ControlsSeparatorsAndNonCharacters, RefusedCodePointTest,
                         ::testing::ValuesIn(kRefused));

TEST(SceneTextTest, BytesThatAreNotUtf8AreRefusedFromSet) {
  for (const std::string& bad : {std::string("\xFF"), std::string("\xC0\xAF"),
                                 std::string("\xED\xA0\x80"), std::string("\xE2\x82")}) {
    const std::string problem = problemOf(kBody, {parseSetExpression("title=a" + bad)});
    EXPECT_NE(problem.find("title: "), std::string::npos) << problem;
    EXPECT_NE(problem.find("not UTF-8 (at byte "), std::string::npos) << problem;
  }
}

TEST(SceneTextTest, PrintableTextOfEveryScriptIsKept) {
  // Accents, Greek, CJK, an emoji beyond the BMP, Arabic with the isolates numbers need.
  const std::string title = "K\u00f6rper \u03c9 \u6f22\u5b57 \U0001F600 \u2066\u0661\u2069";
  const SceneDesc scene = parseSceneText("title = \"" + title + "\"\n" + kBody, "s.toml");
  EXPECT_EQ(scene.title, title);
  EXPECT_EQ(problemOf(kBody, {parseSetExpression("title=" + title)}), "");
}

}  // namespace
}  // namespace collide::scene
