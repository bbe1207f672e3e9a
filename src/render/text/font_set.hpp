#pragma once
// Private: the fonts one painter draws text with (render/text/script_fonts.hpp): the default font
// first, then the language's script font, and which of them draws each character.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "render/text/font.hpp"
#include "render/text/script_fonts.hpp"

namespace collide::render {

class FontSet {
 public:
  // Loads every file. Throws FontError naming one that cannot be loaded.
  explicit FontSet(const TextFonts& fonts);

  // The fonts text is drawn with (the math font, which font() also reaches, is not counted).
  int size() const { return text_fonts_; }
  // The OpenType MATH font's index (never chosen by fontFor); -1: none.
  int mathFont() const { return math_font_; }
  Font& font(int index) { return *fonts_[static_cast<std::size_t>(index)]; }
  Font& primary() { return *fonts_.front(); }
  const std::string& languageTag() const { return language_tag_; }
  bool rightToLeft() const { return right_to_left_; }

  // The font that draws `c`, given the font of the character before it (-1 at the start).
  // Letters of Latin, Greek and Cyrillic, digits and common punctuation prefer the default
  // font; other scripts the script font (DejaVu has some Arabic letters, but the language's
  // font writes them as its readers expect). Spaces, joiners and combining marks stay in the
  // font of the text around them. A character no font has gets the default font's missing box.
  int fontFor(char32_t c, int previous);
  // Line metrics at an em size: the default font's, whatever the script, so a frame is laid out
  // alike in every language. (The script fonts' own line metrics leave room for stacks of marks
  // the words on a frame never have: Noto Sans Arabic's span 2.1 em against DejaVu's 1.17 em.)
  FontMetrics metrics(int pixel_size);

 private:
  std::vector<std::unique_ptr<Font>> fonts_;
  std::string language_tag_;
  int math_font_ = -1;
  int text_fonts_ = 0;  // fonts fontFor chooses from: all but the math font
  bool right_to_left_ = false;
};

}  // namespace collide::render
