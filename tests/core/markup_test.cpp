// SPDX-License-Identifier: MIT
// The one escaping rule for SVG, MathML and the lesson page.
#include "core/markup.hpp"

#include <gtest/gtest.h>

namespace collide {
namespace {

TEST(MarkupTest, TheFiveSpecialCharactersBecomeReferences) {
  EXPECT_EQ(core::markupEscaped(R"(a<b & "c" > 'd')"),
            "a&lt;b &amp; &quot;c&quot; &gt; &#39;d&#39;");
}

TEST(MarkupTest, OtherTextIsKeptByteForByte) {
  const std::string arabic_and_subscript = "\u0645\u2081 = 1.00 kg";
  EXPECT_EQ(core::markupEscaped(arabic_and_subscript), arabic_and_subscript);
  EXPECT_EQ(core::markupEscaped(""), "");
}

TEST(MarkupTest, AReferenceAlreadyWrittenIsEscapedAgain) {
  // A scene's name is text, not markup: "&amp;" typed by a user must read "&amp;" on the page.
  EXPECT_EQ(core::markupEscaped("&amp;"), "&amp;amp;");
}

TEST(MarkupTest, AppendingAddsAfterWhatIsThere) {
  std::string out = "<text>";
  core::appendMarkupEscaped(out, "x<y");
  EXPECT_EQ(out, "<text>x&lt;y");
}

}  // namespace
}  // namespace collide
