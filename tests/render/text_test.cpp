// FreeType text without GL: UTF-8, sub- and superscripts, measuring, eliding, atlas packing.
#include "render/text/text.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "render/renderer.hpp"
#include "render/text/font_set.hpp"
#include "render/text/glyph_atlas.hpp"

namespace collide::render {
namespace {

class TextTest : public ::testing::Test {
 protected:
  FontSet fonts{textFontsFor(defaultFontPath(), "en")};
  GlyphAtlas atlas{fonts};

  const AtlasGlyph& glyph(char32_t c, int size) {
    return atlas.glyph(0, fonts.primary().glyphIndex(c), size);
  }
  TextPainter painter{atlas};
};

TEST(Utf8Test, DecodesAndEncodesRoundTrip) {
  const std::string text = "v₁′ = −0.25 m/s, Σp, ×4";
  const std::u32string decoded = decodeUtf8(text);
  EXPECT_EQ(decoded[0], U'v');
  EXPECT_EQ(decoded[1], U'\u2081');
  EXPECT_EQ(decoded[2], U'\u2032');
  EXPECT_EQ(encodeUtf8(decoded), text);
}

TEST(Utf8Test, MalformedBytesBecomeReplacementCharacters) {
  const std::u32string decoded =
      decodeUtf8(std::string("a\xff"
                             "b\xe2\x82",
                             5));
  // A truncated sequence at the end: one replacement per byte.
  ASSERT_EQ(decoded.size(), 5u);
  EXPECT_EQ(decoded[1], U'\uFFFD');
  EXPECT_EQ(decoded[2], U'b');
  EXPECT_EQ(decoded[3], U'\uFFFD');
  EXPECT_EQ(decoded[4], U'\uFFFD');
}

TEST_F(TextTest, SubscriptIsASmallerDigitBelowTheBaseline) {
  std::vector<TextVertex> plain, sub;
  painter.draw("1", {0.0, 100.0}, 40.0, {}, HAlign::kLeft, VAlign::kBaseline, plain);
  painter.draw("₁", {0.0, 100.0}, 40.0, {}, HAlign::kLeft, VAlign::kBaseline, sub);
  ASSERT_EQ(plain.size(), 6u);
  ASSERT_EQ(sub.size(), 6u);
  const float plain_h = plain[2].y_px - plain[0].y_px, sub_h = sub[2].y_px - sub[0].y_px;
  EXPECT_NEAR(sub_h / plain_h, kScriptScale, 0.1);
  EXPECT_GT(sub[2].y_px, plain[2].y_px);  // the subscript's bottom is lower
  EXPECT_LT(painter.width("v₁", 40.0), painter.width("v1", 40.0));
}

TEST_F(TextTest, SuperscriptIsRaised) {
  std::vector<TextVertex> plain, sup;
  painter.draw("2", {0.0, 100.0}, 40.0, {}, HAlign::kLeft, VAlign::kBaseline, plain);
  painter.draw("²", {0.0, 100.0}, 40.0, {}, HAlign::kLeft, VAlign::kBaseline, sup);
  EXPECT_LT(sup[0].y_px, plain[0].y_px);
}

TEST_F(TextTest, GlyphQuadsSitOnWholePixels) {
  std::vector<TextVertex> quads;
  painter.draw("m₂ = 1.25 kg", {10.3, 20.7}, 15.0, {}, HAlign::kCenter, VAlign::kMiddle, quads);
  ASSERT_FALSE(quads.empty());
  for (const TextVertex& v : quads) {
    EXPECT_EQ(v.x_px, std::round(v.x_px));
    EXPECT_EQ(v.y_px, std::round(v.y_px));
  }
}

// text.frag finds a pixel's texel as the pixel plus one offset per glyph (a flat input, so that
// text and shapes share llvmpipe's triangle set-up): every glyph quad must map one pixel to one
// texel, its six vertices sharing that offset, in whole texels.
TEST_F(TextTest, EachGlyphQuadMapsOnePixelToOneTexel) {
  std::vector<TextVertex> quads;
  painter.draw("m₂ = 1.25 kg, v² ≈ x", {10.3, 20.7}, 15.0, {}, HAlign::kCenter, VAlign::kMiddle,
               quads);
  painter.draw("E = ½mv²", {200.6, 61.2}, 33.0, {}, HAlign::kRight, VAlign::kBaseline, quads);
  ASSERT_EQ(quads.size() % 6, 0u);
  ASSERT_GE(quads.size(), 6u * 10);
  for (std::size_t quad = 0; quad < quads.size(); quad += 6) {
    const float du = quads[quad].u_texel - quads[quad].x_px;
    const float dv = quads[quad].v_texel - quads[quad].y_px;
    EXPECT_EQ(du, std::round(du)) << "quad " << quad / 6;
    EXPECT_EQ(dv, std::round(dv)) << "quad " << quad / 6;
    for (std::size_t corner = quad; corner < quad + 6; ++corner) {
      EXPECT_EQ(quads[corner].u_texel - quads[corner].x_px, du) << "quad " << quad / 6;
      EXPECT_EQ(quads[corner].v_texel - quads[corner].y_px, dv) << "quad " << quad / 6;
    }
  }
}

TEST_F(TextTest, AlignmentMovesTheBox) {
  std::vector<TextVertex> out;
  const frame::PixelRect left =
      painter.draw("KE", {100.0, 50.0}, 20.0, {}, HAlign::kLeft, VAlign::kBaseline, out);
  const frame::PixelRect right =
      painter.draw("KE", {100.0, 50.0}, 20.0, {}, HAlign::kRight, VAlign::kBaseline, out);
  EXPECT_DOUBLE_EQ(left.x0, 100.0);
  EXPECT_NEAR(right.x1, 100.0, 1e-9);
  EXPECT_NEAR(left.width(), painter.width("KE", 20.0), 1e-9);
}

TEST_F(TextTest, ElideCutsWithAnEllipsis) {
  const std::string text = "a long caption that will not fit";
  EXPECT_EQ(painter.elide(text, 15.0, 1e6), text);
  const std::string cut = painter.elide(text, 15.0, 80.0);
  EXPECT_LE(painter.width(cut, 15.0), 80.0);
  EXPECT_NE(cut.find("…"), std::string::npos);
}

TEST_F(TextTest, FitWholeDropsWholePartsAndNeverPartsANameFromItsValue) {
  const std::string text = "Contact force, impulse 2.27 N·s; from t = 0.975 s";
  EXPECT_EQ(painter.fitWhole(text, 15.0, 1e6), text);
  // What drops parts ends in an ellipsis, so the reader sees that something is left out.
  const std::string clause = "Contact force, impulse 2.27 N·s\u2026";
  const double clause_w = painter.width(clause, 15.0);
  EXPECT_EQ(painter.fitWhole(text, 15.0, clause_w + 1.0), clause);
  EXPECT_EQ(painter.fitWhole(text, 15.0, clause_w - 1.0), "Contact force\u2026");
  // Only words fit: "t =" without its time, or "t" before " =", is never a place to stop.
  const std::string reading = "energy from t = 0.975 s";
  const double before_t = painter.width("energy from t =\u2026", 15.0);
  EXPECT_EQ(painter.fitWhole(reading, 15.0, before_t + 1.0), "energy from\u2026");
  // Nor a number without its unit.
  const std::string amount = "impulse 2.27 N·s";
  const double before_unit = painter.width("impulse 2.27\u2026", 15.0);
  EXPECT_EQ(painter.fitWhole(amount, 15.0, before_unit + 1.0), "impulse\u2026");
}

TEST_F(TextTest, FitWholeKeepsTheLongestListOfWholeItemsThatFits) {
  // A caption listing many velocities: the result must be the longest run of whole items that fits,
  // found here by trying every item count in turn (the painter bisects).
  std::string text;
  std::vector<std::string> beginnings;  // "v1 = 1.11 m/s, ..., vk = 1.(10+k) m/s", k < 60
  for (int k = 1; k <= 60; ++k) {
    if (k > 1) beginnings.push_back(text);
    text += (k > 1 ? ", v" : "v") + std::to_string(k) + " = 1." + std::to_string(10 + k) + " m/s";
  }
  for (const double room : {300.0, 455.0, 900.0, 2000.0}) {
    std::string expected;
    for (const std::string& beginning : beginnings) {
      const std::string candidate = beginning + "\u2026";
      if (painter.width(candidate, 15.0) <= room) expected = candidate;
    }
    ASSERT_FALSE(expected.empty()) << room;
    EXPECT_EQ(painter.fitWhole(text, 15.0, room), expected) << room;
  }
}

TEST_F(TextTest, AStringDrawnEveryFrameStaysShapedWhileNewOnesComeAndGo) {
  // Each frame draws its title again and one new clock reading; the title is never shaped anew,
  // however long the video.
  const ShapedLine* title = &painter.shaped("An ideal gas", 15.0);
  for (int frame = 0; frame < 3000; ++frame) {
    painter.shaped(std::to_string(frame) + " ms", 15.0);
    EXPECT_EQ(&painter.shaped("An ideal gas", 15.0), title) << "frame " << frame;
  }
}

TEST_F(TextTest, WrapBreaksBetweenClausesThenWordsAndKeepsNumbersWithUnits) {
  const std::string info = "collisions: 1   \u03a3p = +2.00 kg·m/s";
  const double first = painter.width("collisions: 1", 15.0);
  const double second = painter.width("\u03a3p = +2.00 kg·m/s", 15.0);
  EXPECT_EQ(painter.wrap(info, 15.0, std::max(first, second) + 1.0, 2),
            (std::vector<std::string>{"collisions: 1", "\u03a3p = +2.00 kg·m/s"}));
  // Words: a number stays with its unit and with the word before it ("of 1.38 J").
  const std::string caption = "energy lost 0.68 J of 1.38 J";
  const double room = painter.width("energy lost 0.68 J of 1.38", 15.0) + 1.0;
  EXPECT_EQ(painter.wrap(caption, 15.0, room, 2),
            (std::vector<std::string>{"energy lost 0.68 J", "of 1.38 J"}));
  // More than the lines hold: the last one drops whole parts, visibly.
  const std::vector<std::string> one = painter.wrap(caption, 15.0, room, 1);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_TRUE(one.front().ends_with("\u2026")) << one.front();
  EXPECT_LE(painter.width(one.front(), 15.0), room);
}

TEST_F(TextTest, AtlasKeepsGlyphsAndGrowsWithoutMovingThem) {
  const AtlasGlyph first = glyph(U'A', 30);
  const int height = atlas.height();
  for (int size = 20; size < 140; size += 4) {
    for (char32_t c = U'A'; c <= U'Z'; ++c) glyph(c, size);
  }
  EXPECT_GT(atlas.height(), height);
  const AtlasGlyph again = glyph(U'A', 30);
  EXPECT_EQ(again.x, first.x);
  EXPECT_EQ(again.y, first.y);
}

// What drawing a video's frames only where they change relies on (gl_rasterizer.cpp): a glyph
// placed later never changes the texels an earlier glyph's quad can read, its box and the texel
// of padding around it, not even when the atlas grows.
TEST_F(TextTest, GlyphsPlacedLaterLeaveTheTexelsAroundEarlierGlyphsAsTheyWere) {
  struct Kept {
    AtlasGlyph glyph;
    std::vector<std::uint8_t> texels;  // the box grown by one texel on every side, row by row
  };
  const auto around = [&](const AtlasGlyph& g) {
    std::vector<std::uint8_t> texels;
    for (int y = g.y - 1; y <= g.y + g.rows; ++y) {
      for (int x = g.x - 1; x <= g.x + g.width; ++x) {
        texels.push_back(atlas.texels()[static_cast<std::size_t>(y) * atlas.width() + x]);
      }
    }
    return texels;
  };
  std::vector<Kept> kept;
  for (const char32_t c : {U'W', U'g', U'1', U'm'}) {
    const AtlasGlyph& g = glyph(c, 24);
    kept.push_back({g, around(g)});
  }
  const int height_before = atlas.height();
  for (int size = 20; size <= 120; size += 4) {
    for (char32_t c = U'!'; c <= U'~'; ++c) glyph(c, size);
  }
  ASSERT_GT(atlas.height(), height_before) << "the atlas should have grown";
  for (const Kept& k : kept) {
    EXPECT_EQ(around(k.glyph), k.texels) << "glyph at texel " << k.glyph.x << "," << k.glyph.y;
  }
}

TEST(FontTest, MissingFontIsAnInputErrorNamingThePath) {
  try {
    Font font("/no/such/font.ttf");
    FAIL() << "no error";
  } catch (const FontError& error) {
    EXPECT_NE(std::string(error.what()).find("/no/such/font.ttf"), std::string::npos);
    EXPECT_EQ(error.code(), core::ExitCode::kBadInput);
  }
}

}  // namespace
}  // namespace collide::render
