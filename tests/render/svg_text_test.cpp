// SPDX-License-Identifier: MIT
// An SVG figure's text as strings (render/svg_text.hpp): a line of Latin is one <tspan> whose
// characters are the words as written, with one x per character at the whole pixel the layout
// gives; Arabic reads from the right as one string anchored at its right end, its commas and
// spaces with it; a Devanagari word with its conjuncts is one string the viewer shapes; letters
// with combining marks keep their characters and the width the layout gave them.
#include <gtest/gtest.h>

#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "frame/layout.hpp"
#include "frame_models.hpp"
#include "render/text/script_fonts.hpp"
#include "render/text/text_metrics.hpp"
#include "render/vector/vector_painter.hpp"
#include "svg_positions.hpp"

namespace collide::render {
namespace {

constexpr double kPtPerPx = 72.0 / 96.0;  // a screen figure: 96 layout pixels per inch

struct Tspan {
  std::string attributes, text;
  std::vector<double> xs;  // its x attribute's values
};

// The <tspan> elements of `svg` in document order (the test strings hold no XML escapes).
std::vector<Tspan> tspans(const std::string& svg) {
  std::vector<Tspan> out;
  const std::regex element("<tspan ([^>]*)>([^<]*)</tspan>");
  const std::regex x_attribute("\\bx=\"([^\"]*)\"");
  for (std::sregex_iterator it(svg.begin(), svg.end(), element), end; it != end; ++it) {
    Tspan t{(*it)[1], (*it)[2], {}};
    std::smatch x;
    if (std::regex_search(t.attributes, x, x_attribute)) {
      std::istringstream values(x[1].str());
      for (double v; values >> v;) t.xs.push_back(v);
    }
    out.push_back(t);
  }
  return out;
}

const Tspan* holding(const std::vector<Tspan>& all, const std::string& text) {
  for (const Tspan& t : all) {
    if (t.text.find(text) != std::string::npos) return &t;
  }
  return nullptr;
}

std::size_t codePoints(const std::string& utf8) {
  std::size_t n = 0;
  for (unsigned char c : utf8) n += (c & 0xC0) != 0x80 ? 1 : 0;
  return n;
}

// The 640x360 SVG of the labelled blocks titled `title`, in `lang`'s fonts and direction.
std::string figureTitled(const std::string& title, const char* lang) {
  frame::FrameModel frame = testing::labelledBlocks();
  frame.title = title;
  frame.lang = lang;
  VectorFigureOptions options;
  options.format = VectorFormat::kSvg;
  options.width_px = 640;
  options.height_px = 360;
  options.text_fonts = textFontsFor(defaultFontPath(), lang);
  frame.style.right_to_left = options.text_fonts.right_to_left;
  return paintVectorFigure(frame, options);
}

TEST(SvgTextTest, ALatinLineIsOneStringWithOneXPerCharacter) {
  const std::string title = "Inelastic collision, e = 0.5";
  const std::string svg = figureTitled(title, "en");
  // The words as a search finds them in the file.
  EXPECT_NE(svg.find(">" + title + "</tspan>"), std::string::npos);
  const std::vector<Tspan> all = tspans(svg);
  const Tspan* line = holding(all, title);
  ASSERT_NE(line, nullptr);
  ASSERT_EQ(line->xs.size(), title.size());  // ASCII: one value per character
  for (std::size_t k = 1; k < line->xs.size(); ++k) EXPECT_GT(line->xs[k], line->xs[k - 1]) << k;
  // On whole layout pixels (three quarters of a point each), the first at the header's left edge.
  for (double x : line->xs) EXPECT_NEAR(std::remainder(x / kPtPerPx, 1.0), 0.0, 1e-3) << x;
  const frame::FrameModel frame = testing::labelledBlocks();
  const frame::PixelRect header = frame::computeFrameLayout(640, 360, frame::shapeOf(frame)).header;
  EXPECT_NEAR(line->xs.front(), header.x0 * kPtPerPx, 0.5 * kPtPerPx);
  // Every list holds one value per character.
  for (const Tspan& t : all) {
    if (t.xs.size() > 1) {
      EXPECT_EQ(t.xs.size(), codePoints(t.text)) << t.text;
    }
  }
  EXPECT_FALSE(test::withEachCharacterPlaced(svg).empty());
}

TEST(SvgTextTest, ArabicReadsFromTheRightAsOneStringWithItsComma) {
  const std::string words = "تصادم غير مرن";
  const std::vector<Tspan> all = tspans(figureTitled(words + "، e = 0.5", "ar"));
  const Tspan* arabic = holding(all, words);
  ASSERT_NE(arabic, nullptr) << "the words are one string";
  EXPECT_EQ(arabic->xs.size(), 1u) << "anchored once, shaped by the viewer: " << arabic->attributes;
  EXPECT_NE(arabic->attributes.find("direction=\"rtl\""), std::string::npos) << arabic->attributes;
  EXPECT_NE(arabic->attributes.find("Noto Sans Arabic"), std::string::npos) << arabic->attributes;
  // The Arabic comma has no direction of its own: it reads from the right with the words, so it
  // follows them on the left and the space after it lies further left still.
  const Tspan* comma = holding(all, "،");
  ASSERT_NE(comma, nullptr);
  EXPECT_NE(comma->attributes.find("direction=\"rtl\""), std::string::npos) << comma->attributes;
  EXPECT_LE(comma->xs.front(), arabic->xs.front());
  const Tspan* latin = holding(all, "e");
  ASSERT_NE(latin, nullptr);
  EXPECT_LT(latin->xs.front(), comma->xs.front()) << "the Latin part lies left of the comma";
  EXPECT_EQ(latin->attributes.find("direction"), std::string::npos) << latin->attributes;
}

TEST(SvgTextTest, DevanagariConjunctsStayInOneStringTheViewerShapes) {
  // "pra", "tya", "stha", "ṭṭa": conjuncts, several characters to a glyph or glyphs to a
  // character; a list of one x per character would tear them apart.
  const std::string words = "अप्रत्यास्थ संघट्ट";
  const std::vector<Tspan> all = tspans(figureTitled(words + ", e = 0.5", "hi"));
  const Tspan* hindi = holding(all, words);
  ASSERT_NE(hindi, nullptr) << "the words are one string";
  EXPECT_EQ(hindi->xs.size(), 1u) << hindi->attributes;
  EXPECT_NE(hindi->attributes.find("Noto Sans Devanagari"), std::string::npos);
}

// The font size of the <text> element that holds `text`, in user units.
double fontSizeOfLineHolding(const std::string& svg, const std::string& text) {
  const std::size_t at = svg.find(text);
  const std::size_t start = svg.rfind("<text ", at);
  std::smatch size;
  const std::string tag = svg.substr(start, svg.find('>', start) - start);
  if (at == std::string::npos || start == std::string::npos ||
      !std::regex_search(tag, size, std::regex("font-size=\"([0-9.]+)px\""))) {
    ADD_FAILURE() << "no <text> holds " << text;
    return 0.0;
  }
  return std::stod(size[1]);
}

TEST(SvgTextTest, ALetterWithAMarkKeepsItsCharactersAndItsWidth) {
  // "e" and a combining acute accent: one cluster of two characters in the default font, which
  // a list of one x per character would part. The piece is anchored once, with the width the
  // layout gave it: that of the same words with the accented letter precomposed (DejaVu draws
  // both alike), from the first letter's x to the last's plus the last's advance ('t': under
  // half an em).
  const std::string decomposed = "Cafe\u0301 au lait", composed = "Caf\u00e9 au lait";
  const std::vector<Tspan> marked = tspans(figureTitled(decomposed, "en"));
  const Tspan* line = holding(marked, decomposed);
  ASSERT_NE(line, nullptr);
  EXPECT_EQ(line->xs.size(), 1u) << line->attributes;
  std::smatch length;
  ASSERT_TRUE(std::regex_search(line->attributes, length, std::regex("textLength=\"([0-9.]+)\"")))
      << line->attributes;
  const std::string plain_svg = figureTitled(composed, "en");
  const std::vector<Tspan> plain = tspans(plain_svg);
  const Tspan* plain_line = holding(plain, composed);
  ASSERT_NE(plain_line, nullptr);
  ASSERT_EQ(plain_line->xs.size(), codePoints(composed));
  EXPECT_NEAR(line->xs.front(), plain_line->xs.front(), 1e-9);
  const double span = plain_line->xs.back() - plain_line->xs.front();
  const double em = fontSizeOfLineHolding(plain_svg, composed);
  EXPECT_GT(std::stod(length[1]), span);
  EXPECT_LT(std::stod(length[1]), span + 0.5 * em);
}

}  // namespace
}  // namespace collide::render
