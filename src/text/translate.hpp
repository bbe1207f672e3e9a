#pragma once
// Translating the text people read on pictures, in captions, alt text and charts: a small
// gettext-style API over the active language's catalogue (text/language.hpp). The source strings
// are English and are extracted from the code into po/collide.pot by xgettext with these keywords
// (scripts/update-po):
//   tr("msgid")                         a message
//   trc("context", "msgid")             a message whose English is ambiguous ("lost" as in energy)
//   trn("singular", "plural", n)        a message with a count: the form for n by the language's
//   trnc("context", "singular", "plural", n)   Plural-Forms rule
//   N_("msgid"), NC_("context", "msgid")   mark a string in a table for extraction only; tr()
//                                       or trc() it where it is shown
// Placeholders are named, in braces, so translators can move them: fill("{mass} at {speed}",
// {{"mass", ...}, {"speed", ...}}). A comment starting "TRANSLATORS:" just before a call goes into
// the template for the translator.
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace collide::text {

std::string tr(std::string_view msgid);
std::string trc(std::string_view context, std::string_view msgid);
std::string trn(std::string_view singular, std::string_view plural, unsigned long n);
std::string trnc(std::string_view context, std::string_view singular, std::string_view plural,
                 unsigned long n);

// Marks a literal for extraction only; it is translated where it is shown.
constexpr const char* N_(const char* msgid) {
  return msgid;
}

// Marks a literal with its context for extraction only; trc() it where it is shown.
constexpr const char* NC_(const char* /*context*/, const char* msgid) {
  return msgid;
}

// `pattern` with every "{name}" replaced by its value; a name without a value stays as written.
using Placeholder = std::pair<std::string_view, std::string_view>;
std::string fill(std::string_view pattern, std::initializer_list<Placeholder> values);

// The placeholder names of a message, in order of appearance ("{mass} at {speed}" -> mass,
// speed), for the catalogue checks.
std::vector<std::string> placeholderNames(std::string_view message);

// The pseudo-language's version of an English string: letters accented, 40 % longer (padding
// inside brackets), placeholders kept.
std::string pseudoTranslate(std::string_view english);

}  // namespace collide::text
