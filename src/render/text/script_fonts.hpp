#pragma once
// The fonts text in a language is drawn with: the default font (DejaVu Sans: Latin, Greek,
// Cyrillic; or the user's --font) first, then the font of the language's script, found through
// fontconfig: Noto for Arabic and Devanagari (Debian fonts-noto-core), Noto CJK for Chinese,
// Japanese and Korean (fonts-noto-cjk). No third-party header here.
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace collide::render {

// A font file and the face in it (TrueType collections such as Noto CJK hold several).
struct FontFile {
  std::string path;
  int face_index = 0;
  bool operator==(const FontFile&) const = default;
};

// What text in one language is shaped with.
struct TextFonts {
  std::vector<FontFile> files;  // the default font first, then the script font (if any)
  // The OpenType MATH font the working is typeset with (render/text/math_typesetter.hpp), last
  // in `files` and never chosen for ordinary text; -1: none installed.
  int math_font = -1;
  std::string language_tag;    // BCP 47 ("ja"): HarfBuzz picks the language's glyph forms
  bool right_to_left = false;  // paragraphs read from the right (Arabic)
};

// A font a language's script needs beyond the default one.
struct ScriptFont {
  std::string family;          // fontconfig family, "Noto Sans Arabic"
  std::string debian_package;  // "fonts-noto-core"
};

// The font a language needs beyond the default one; nullopt for Latin, Greek and Cyrillic.
std::optional<ScriptFont> scriptFontFor(std::string_view language_tag);

// That font's file through fontconfig; nullopt when it is not installed (fontconfig answers
// every query with some font: only the family asked for counts).
std::optional<FontFile> findFontFile(const ScriptFont& font);

// The math font (TeX Gyre DejaVu Math: DejaVu's letters with an OpenType MATH table), through
// fontconfig; nullopt when neither Debian's fonts-dejavu-extra nor fonts-texgyre-math is installed.
std::optional<FontFile> findMathFont();

// The fonts for text in `language_tag` (empty: the active language, text/language.hpp), the
// default font `default_font_path` first. Throws core::InputError (exit 2) naming the Debian
// package to install when the language's font is missing.
TextFonts textFontsFor(const std::string& default_font_path, std::string_view language_tag = {});

}  // namespace collide::render
