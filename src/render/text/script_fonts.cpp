#include "render/text/script_fonts.hpp"

#include <fontconfig/fontconfig.h>

#include <memory>
#include <mutex>

#include "core/error.hpp"
#include "text/language.hpp"

namespace collide::render {
namespace {

std::string primarySubtag(std::string_view tag) {
  return std::string(tag.substr(0, tag.find('-')));
}

using PatternPtr = std::unique_ptr<FcPattern, decltype(&FcPatternDestroy)>;

}  // namespace

std::optional<ScriptFont> scriptFontFor(std::string_view language_tag) {
  const std::string language = primarySubtag(language_tag);
  // The sans-serif designs, to sit beside DejaVu Sans in one line.
  if (language == "ar" || language == "fa" || language == "ur") {
    return ScriptFont{"Noto Sans Arabic", "fonts-noto-core"};
  }
  if (language == "hi" || language == "mr" || language == "ne") {
    return ScriptFont{"Noto Sans Devanagari", "fonts-noto-core"};
  }
  if (language == "ja") return ScriptFont{"Noto Sans CJK JP", "fonts-noto-cjk"};
  if (language == "ko") return ScriptFont{"Noto Sans CJK KR", "fonts-noto-cjk"};
  if (language == "zh") {
    const bool traditional = language_tag.find("Hant") != std::string_view::npos;
    return ScriptFont{traditional ? "Noto Sans CJK TC" : "Noto Sans CJK SC", "fonts-noto-cjk"};
  }
  return std::nullopt;
}

std::optional<FontFile> findFontFile(const ScriptFont& font) {
  // fontconfig's default configuration is process-wide; FcFontMatch may run on several threads
  // (batch workers), its first loading once.
  static std::mutex fontconfig_mutex;
  const std::lock_guard<std::mutex> lock(fontconfig_mutex);
  if (FcInit() == FcFalse) return std::nullopt;
  PatternPtr pattern(FcPatternCreate(), &FcPatternDestroy);
  FcPatternAddString(pattern.get(), FC_FAMILY,
                     reinterpret_cast<const FcChar8*>(font.family.c_str()));
  FcPatternAddInteger(pattern.get(), FC_WEIGHT, FC_WEIGHT_REGULAR);
  FcPatternAddInteger(pattern.get(), FC_SLANT, FC_SLANT_ROMAN);
  FcConfigSubstitute(nullptr, pattern.get(), FcMatchPattern);
  FcDefaultSubstitute(pattern.get());
  FcResult result = FcResultNoMatch;
  PatternPtr match(FcFontMatch(nullptr, pattern.get(), &result), &FcPatternDestroy);
  if (match == nullptr) return std::nullopt;
  FcChar8* file = nullptr;
  if (FcPatternGetString(match.get(), FC_FILE, 0, &file) != FcResultMatch) return std::nullopt;
  bool family_matches = false;
  FcChar8* family = nullptr;
  for (int k = 0; FcPatternGetString(match.get(), FC_FAMILY, k, &family) == FcResultMatch; ++k) {
    family_matches = family_matches || font.family == reinterpret_cast<const char*>(family);
  }
  if (!family_matches) return std::nullopt;
  int index = 0;
  if (FcPatternGetInteger(match.get(), FC_INDEX, 0, &index) != FcResultMatch) index = 0;
  return FontFile{reinterpret_cast<const char*>(file), index};
}

TextFonts textFontsFor(const std::string& default_font_path, std::string_view language_tag) {
  const text::Language& language =
      language_tag.empty() ? text::activeLanguage() : text::findLanguage(language_tag);
  TextFonts fonts;
  fonts.files.push_back({default_font_path, 0});
  fonts.language_tag = language.tag;
  fonts.right_to_left = language.right_to_left;
  const std::optional<ScriptFont> needed = scriptFontFor(language.tag);
  if (!needed) return fonts;
  const std::optional<FontFile> file = findFontFile(*needed);
  if (!file) {
    throw core::InputError("language " + language.tag + ": its text needs the font " +
                           needed->family + ", which is not installed; install the Debian " +
                           "package " + needed->debian_package +
                           " (scripts/install-packages does)");
  }
  fonts.files.push_back(*file);
  return fonts;
}

}  // namespace collide::render
