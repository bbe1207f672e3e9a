#include "render/text/script_fonts.hpp"

#include <fontconfig/fontconfig.h>
#include <sys/mman.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>

#include "core/error.hpp"
#include "render/text/text_metrics.hpp"
#include "text/language.hpp"

namespace collide::render {
namespace {

std::string primarySubtag(std::string_view tag) {
  return std::string(tag.substr(0, tag.find('-')));
}

using PatternPtr = std::unique_ptr<FcPattern, decltype(&FcPatternDestroy)>;

std::atomic<bool> fontconfig_messages_shown{true};

// What was written to the file `fd` refers to, from its start.
std::string readBack(int fd) {
  std::string text;
  if (lseek(fd, 0, SEEK_SET) != 0) return text;
  char buffer[4096];
  for (ssize_t got; (got = read(fd, buffer, sizeof buffer)) > 0;) {
    text.append(buffer, static_cast<std::size_t>(got));
  }
  return text;
}

// FcInit with what fontconfig writes to stderr meanwhile (the errors and warnings of its
// configuration files, which it prints unasked and cannot be told not to) caught in a file in
// memory and returned. Without such a file, FcInit as it is.
std::string initFontconfigCaught(FcBool& loaded) {
  std::fflush(stderr);
  const int caught = memfd_create("collide-fontconfig", MFD_CLOEXEC);
  const int saved = caught >= 0 ? dup(STDERR_FILENO) : -1;
  if (saved < 0 || dup2(caught, STDERR_FILENO) < 0) {
    if (saved >= 0) close(saved);
    if (caught >= 0) close(caught);
    loaded = FcInit();
    return {};
  }
  loaded = FcInit();
  std::fflush(stderr);
  dup2(saved, STDERR_FILENO);
  close(saved);
  std::string messages = readBack(caught);
  close(caught);
  return messages;
}

// fontconfig loads its configuration on its first use in the process: then its messages are
// caught, and passed on to stderr unless -q asked for quiet. The caller holds the mutex.
bool initFontconfig() {
  static bool first = true;
  if (!first) return FcInit() != FcFalse;
  first = false;
  FcBool loaded = FcFalse;
  const std::string messages = initFontconfigCaught(loaded);
  if (fontconfig_messages_shown && !messages.empty()) std::cerr << messages << std::flush;
  return loaded != FcFalse;
}

}  // namespace

void showFontconfigMessages(bool shown) {
  fontconfig_messages_shown = shown;
}

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

namespace {

// The file fontconfig matches for `font`'s family, asked of it (under findFontFile's lock).
std::optional<FontFile> matchFontFile(const ScriptFont& font) {
  if (!initFontconfig()) return std::nullopt;
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

}  // namespace

std::optional<FontFile> findFontFile(const ScriptFont& font) {
  // fontconfig's default configuration is process-wide; FcFontMatch may run on several threads
  // (batch workers), its first loading once.
  static std::mutex fontconfig_mutex;
  // Each family's match, asked once: every painter's fonts (a layout's every frame) look up the
  // math font, and a match costs fontconfig's substitutions and a walk of its font list.
  static std::map<std::string, std::optional<FontFile>> matched;
  const std::lock_guard<std::mutex> lock(fontconfig_mutex);
  const auto found = matched.find(font.family);
  if (found != matched.end()) return found->second;
  return matched.emplace(font.family, matchFontFile(font)).first->second;
}

std::optional<FontFile> findMathFont() {
  for (const ScriptFont& font : {ScriptFont{"DejaVu Math TeX Gyre", "fonts-dejavu-extra"},
                                 ScriptFont{"TeX Gyre DejaVu Math", "fonts-texgyre-math"}}) {
    if (std::optional<FontFile> file = findFontFile(font)) return file;
  }
  return std::nullopt;
}

namespace {

TextFonts withMathFont(TextFonts fonts) {
  if (std::optional<FontFile> math = findMathFont()) {
    fonts.math_font = static_cast<int>(fonts.files.size());
    fonts.files.push_back(*math);
  }
  return fonts;
}

}  // namespace

TextFonts textFontsFor(const std::string& default_font_path, std::string_view language_tag) {
  const text::Language& language =
      language_tag.empty() ? text::activeLanguage() : text::findLanguage(language_tag);
  TextFonts fonts;
  fonts.files.push_back({default_font_path, 0});
  fonts.language_tag = language.tag;
  fonts.right_to_left = language.right_to_left;
  const std::optional<ScriptFont> needed = scriptFontFor(language.tag);
  if (!needed) return withMathFont(std::move(fonts));
  const std::optional<FontFile> file = findFontFile(*needed);
  if (!file) {
    throw core::InputError("language " + language.tag + ": its text needs the font " +
                           needed->family + ", which is not installed; install the Debian " +
                           "package " + needed->debian_package +
                           " (scripts/install-packages does)");
  }
  fonts.files.push_back(*file);
  return withMathFont(std::move(fonts));
}

}  // namespace collide::render
