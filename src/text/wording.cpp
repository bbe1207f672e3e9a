#include "text/wording.hpp"

#include <unicode/locid.h>
#include <unicode/uchar.h>
#include <unicode/unistr.h>
#include <unicode/utf8.h>

#include "text/language.hpp"
#include "text/translate.hpp"

namespace collide::text {

std::string symbol(Symbol which) {
  // TRANSLATORS: the physics symbols, as the physics textbooks of your language write them
  // (keep the English letter where they use it too). They are followed by subscripts (m₁) and
  // primes (v₁′).
  switch (which) {
    case Symbol::kTime:
      return trc("physics symbol: time", "t");
    case Symbol::kMass:
      return trc("physics symbol: mass", "m");
    case Symbol::kVelocity:
      return trc("physics symbol: velocity", "v");
    case Symbol::kMomentum:
      return trc("physics symbol: momentum", "p");
    case Symbol::kRestitution:
      return trc("physics symbol: coefficient of restitution", "e");
    case Symbol::kKineticEnergy:
      return trc("physics symbol: kinetic energy", "KE");
    case Symbol::kPotentialEnergy:
      return trc("physics symbol: potential energy", "PE");
    case Symbol::kPosition:
      return trc("physics symbol: position", "x");
    case Symbol::kForce:
      return trc("physics symbol: force", "F");
    case Symbol::kAngularVelocity:
      return trc("physics symbol: angular velocity", "ω");
  }
  return "?";
}

std::string clauseSeparator() {
  // TRANSLATORS: between the clauses of a caption ("t = 1 s; energy lost ..."), with its space.
  return trc("punctuation", "; ");
}

std::string listSeparator() {
  // TRANSLATORS: between the items of a list ("v₁ = 1 m/s, v₂ = 2 m/s"), with its space.
  return trc("punctuation", ", ");
}

std::string sentenceGap() {
  const std::string& tag = activeLanguage().tag;
  const bool unspaced =
      tag == "ja" || tag.starts_with("ja-") || tag == "zh" || tag.starts_with("zh-");
  return unspaced ? "" : " ";
}

std::string listWithAnd(const std::vector<std::string>& items) {
  if (items.empty()) return "";
  std::string list = items.front();
  for (std::size_t i = 1; i + 1 < items.size(); ++i) list += listSeparator() + items[i];
  if (items.size() == 1) return list;
  // TRANSLATORS: the last two items of a list: "{list} and {last}" ("a, b and c").
  return fill(tr("{list} and {last}"), {{"list", list}, {"last", items.back()}});
}

std::string equation(const std::string& name, const std::string& value) {
  return name + " = " + value;
}

std::string sentenceStart(std::string_view sentence) {
  int32_t after_first = 0;
  UChar32 first = 0;
  U8_NEXT(sentence.data(), after_first, static_cast<int32_t>(sentence.size()), first);
  if (first < 0 || !u_islower(first)) return std::string(sentence);
  icu::UnicodeString upper(first);
  upper.toUpper(icu::Locale(activeLanguage().tag.c_str()));
  std::string result;
  upper.toUTF8String(result);
  result.append(sentence.substr(static_cast<std::size_t>(after_first)));
  return result;
}

}  // namespace collide::text
