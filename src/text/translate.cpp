#include "text/translate.hpp"

#include <cctype>
#include <cmath>

#include "text/language.hpp"

namespace collide::text {
namespace {

bool nameChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.';
}

// The length of a placeholder "{name}" starting at pattern[at], or 0 when there is none there.
std::size_t placeholderAt(std::string_view pattern, std::size_t at) {
  if (pattern[at] != '{') return 0;
  std::size_t end = at + 1;
  while (end < pattern.size() && nameChar(pattern[end])) ++end;
  return end > at + 1 && end < pattern.size() && pattern[end] == '}' ? end + 1 - at : 0;
}

std::string lookup(std::string_view context, std::string_view msgid) {
  const Language& language = activeLanguage();
  if (language.pseudo) return pseudoTranslate(msgid);
  if (const Catalog* catalog = language.catalog()) {
    if (const std::string* found = catalog->find(context, msgid)) return *found;
  }
  return std::string(msgid);
}

std::string lookupPlural(std::string_view context, std::string_view singular,
                         std::string_view plural, unsigned long n) {
  const Language& language = activeLanguage();
  if (language.pseudo) return pseudoTranslate(n == 1 ? singular : plural);
  if (const Catalog* catalog = language.catalog()) {
    if (const std::vector<std::string>* forms = catalog->findPlural(context, singular)) {
      const std::size_t form = static_cast<std::size_t>(catalog->pluralRule().formFor(n));
      if (form < forms->size() && !(*forms)[form].empty()) return (*forms)[form];
    }
  }
  return std::string(n == 1 ? singular : plural);
}

// Accented look-alikes of the ASCII letters, so untranslated text stands out while staying
// readable.
std::string_view accented(char c) {
  static const char* const kLower[26] = {"á", "ƀ", "ç", "đ", "é", "ƒ", "ĝ", "ĥ", "í",
                                         "ĵ", "ķ", "ĺ", "ɱ", "ñ", "ö", "þ", "ǫ", "ŕ",
                                         "š", "ţ", "ü", "ṽ", "ŵ", "ẋ", "ý", "ž"};
  static const char* const kUpper[26] = {"Å", "Ɓ", "Ç", "Đ", "É", "Ƒ", "Ĝ", "Ĥ", "Î",
                                         "Ĵ", "Ķ", "Ĺ", "Ṁ", "Ñ", "Ö", "Þ", "Ǫ", "Ŕ",
                                         "Š", "Ţ", "Û", "Ṽ", "Ŵ", "Ẋ", "Ý", "Ž"};
  if (c >= 'a' && c <= 'z') return kLower[c - 'a'];
  if (c >= 'A' && c <= 'Z') return kUpper[c - 'A'];
  return {};
}

std::size_t codePoints(std::string_view text) {
  std::size_t count = 0;
  for (char c : text) count += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  return count;
}

}  // namespace

std::string tr(std::string_view msgid) {
  return lookup({}, msgid);
}

std::string trc(std::string_view context, std::string_view msgid) {
  return lookup(context, msgid);
}

std::string trn(std::string_view singular, std::string_view plural, unsigned long n) {
  return lookupPlural({}, singular, plural, n);
}

std::string trnc(std::string_view context, std::string_view singular, std::string_view plural,
                 unsigned long n) {
  return lookupPlural(context, singular, plural, n);
}

std::string fill(std::string_view pattern, std::initializer_list<Placeholder> values) {
  std::string out;
  out.reserve(pattern.size() + 16);
  for (std::size_t i = 0; i < pattern.size();) {
    const std::size_t length = placeholderAt(pattern, i);
    if (length > 0) {
      const std::string_view name = pattern.substr(i + 1, length - 2);
      const Placeholder* match = nullptr;
      for (const Placeholder& value : values) {
        if (value.first == name) match = &value;
      }
      if (match != nullptr) {
        out.append(match->second);
        i += length;
        continue;
      }
    }
    out += pattern[i++];
  }
  return out;
}

std::vector<std::string> placeholderNames(std::string_view message) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < message.size(); ++i) {
    const std::size_t length = placeholderAt(message, i);
    if (length == 0) continue;
    names.emplace_back(message.substr(i + 1, length - 2));
    i += length - 1;
  }
  return names;
}

std::string pseudoTranslate(std::string_view english) {
  constexpr double kGrowth = 1.4;  // translations run up to 40 % longer than English
  std::string out = "[";
  for (std::size_t i = 0; i < english.size();) {
    const std::size_t length = placeholderAt(english, i);
    if (length > 0) {
      out.append(english.substr(i, length));
      i += length;
      continue;
    }
    const std::string_view letter = accented(english[i]);
    if (letter.empty()) {
      out += english[i];
    } else {
      out.append(letter);
    }
    ++i;
  }
  // Pad to 1.4 times the length, counting the two brackets in.
  const std::size_t target =
      static_cast<std::size_t>(std::ceil(kGrowth * static_cast<double>(codePoints(english))));
  std::size_t have = codePoints(out) + 1;
  if (have < target) out += ' ';
  for (++have; have < target; ++have) out += "ẍ";
  return out + "]";
}

}  // namespace collide::text
