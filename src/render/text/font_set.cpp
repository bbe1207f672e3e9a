#include "render/text/font_set.hpp"

#include <hb.h>

#include <algorithm>

namespace collide::render {
namespace {

bool followsNeighbours(char32_t c) {
  if (c == U' ' || c == 0x00A0 || c == 0x200C || c == 0x200D || c == 0x202F) return true;
  const hb_unicode_general_category_t category =
      hb_unicode_general_category(hb_unicode_funcs_get_default(), c);
  return category == HB_UNICODE_GENERAL_CATEGORY_NON_SPACING_MARK ||
         category == HB_UNICODE_GENERAL_CATEGORY_SPACING_MARK ||
         category == HB_UNICODE_GENERAL_CATEGORY_ENCLOSING_MARK;
}

bool defaultFontScript(char32_t c) {
  const hb_script_t script = hb_unicode_script(hb_unicode_funcs_get_default(), c);
  return script == HB_SCRIPT_LATIN || script == HB_SCRIPT_GREEK || script == HB_SCRIPT_CYRILLIC ||
         script == HB_SCRIPT_COMMON || script == HB_SCRIPT_INHERITED;
}

}  // namespace

FontSet::FontSet(const TextFonts& fonts)
    : language_tag_(fonts.language_tag),
      math_font_(fonts.math_font),
      text_fonts_(fonts.math_font >= 0 ? fonts.math_font : static_cast<int>(fonts.files.size())),
      right_to_left_(fonts.right_to_left) {
  for (const FontFile& file : fonts.files) {
    fonts_.push_back(std::make_unique<Font>(file.path, file.face_index));
  }
}

int FontSet::fontFor(char32_t c, int previous) {
  if (previous >= 0 && followsNeighbours(c)) return previous;
  const int count = size();
  if (defaultFontScript(c)) {
    for (int i = 0; i < count; ++i) {
      if (font(i).hasGlyph(c)) return i;
    }
  } else {
    for (int i = count - 1; i >= 0; --i) {
      if (font(i).hasGlyph(c)) return i;
    }
  }
  return previous >= 0 ? previous : 0;
}

FontMetrics FontSet::metrics(int pixel_size) {
  return primary().metrics(pixel_size);
}

}  // namespace collide::render
