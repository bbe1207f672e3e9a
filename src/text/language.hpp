#pragma once
// The languages collide ships, chosen by a BCP 47 tag (--lang, the scene key `lang`), and the one
// that text is written in now. English is the source language (no catalogue); every other
// language is a catalogue compiled from po/<tag>.po at build time; "en-XA" is a pseudo-language
// whose strings are 40 % longer with accented letters, for layout tests.
//
// The active language is process-wide, like gettext's: a command picks it once, before it builds
// any text, and it stays fixed while frames are made (threads read it, nobody changes it then).
// Tests switch it with ScopedLanguage.
#include <string>
#include <string_view>
#include <vector>

#include "text/catalog.hpp"

namespace collide::text {

namespace detail {
struct CatalogSlot;  // a language's compiled catalogue, parsed on first use
}

struct Language {
  std::string tag;  // BCP 47 in canonical case: "de", "pt-BR", "zh-Hans"
  detail::CatalogSlot* slot =
      nullptr;                 // nullptr: English (the source strings), the pseudo-language
  bool pseudo = false;         // en-XA: strings made longer and accented at run time
  bool right_to_left = false;  // Arabic, Hebrew, Persian, Urdu: text and layout read from the right

  // The language's catalogue (nullptr: English, the pseudo-language), parsed from its embedded
  // bytes the first time it is asked for: a command pays for the one language it writes in,
  // not for all of them. Safe to call from several threads.
  const Catalog* catalog() const;
};

inline constexpr std::string_view kSourceLanguage = "en";
inline constexpr std::string_view kPseudoLanguage = "en-XA";

// Every shipped language: English first, then the catalogues in tag order, then the
// pseudo-language.
const std::vector<Language>& shippedLanguages();

// "en (English), de (Deutsch), ..., en-XA (pseudo-language)": for error messages and --help.
std::string shippedLanguageList();

// The shipped language for a BCP 47 tag, matched case-insensitively, '_' read as '-', falling
// back from the most specific subtag (de-AT -> de, zh-CN -> zh-Hans, pt -> pt-BR). Throws
// core::InputError naming `typed_by` ("--lang", "lang"), the tag and the shipped languages.
const Language& findLanguage(std::string_view tag, std::string_view typed_by = "--lang");

// The language text is written in now (English until a command chooses).
const Language& activeLanguage();
void setActiveLanguage(const Language& language);

// ISO 639-2 codes of a language (for container metadata): "de" -> deu / ger, "ar" -> ara / ara.
struct Iso639 {
  std::string terminology;    // ISO 639-2/T (MP4)
  std::string bibliographic;  // ISO 639-2/B (Matroska, WebM)
};
Iso639 iso639(std::string_view bcp47_tag);

// The language's name in itself ("Deutsch"), from its catalogue.
std::string languageName(const Language& language);

// Makes `tag` active for a scope (tests), then restores the previous language.
class ScopedLanguage {
 public:
  explicit ScopedLanguage(std::string_view tag);
  ~ScopedLanguage();
  ScopedLanguage(const ScopedLanguage&) = delete;
  ScopedLanguage& operator=(const ScopedLanguage&) = delete;

 private:
  const Language* previous_;
};

}  // namespace collide::text
