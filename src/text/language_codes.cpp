// ISO 639-2 codes of a language for container metadata. The terminology code comes from CLDR
// through ICU (the same data as the number symbols); the bibliographic code differs from it for
// the 20 languages ISO 639-2 lists with two codes, all of them below.
#include <unicode/locid.h>

#include <array>
#include <utility>

#include "text/language.hpp"

namespace collide::text {
namespace {

// ISO 639-2's B/T pairs (loc.gov/standards/iso639-2): terminology, bibliographic.
constexpr std::array<std::pair<std::string_view, std::string_view>, 20> kBibliographic = {{
    {"sqi", "alb"}, {"hye", "arm"}, {"eus", "baq"}, {"mya", "bur"}, {"zho", "chi"},
    {"ces", "cze"}, {"nld", "dut"}, {"fra", "fre"}, {"kat", "geo"}, {"deu", "ger"},
    {"ell", "gre"}, {"isl", "ice"}, {"mkd", "mac"}, {"mri", "mao"}, {"msa", "may"},
    {"fas", "per"}, {"ron", "rum"}, {"slk", "slo"}, {"bod", "tib"}, {"cym", "wel"},
}};

}  // namespace

Iso639 iso639(std::string_view bcp47_tag) {
  UErrorCode status = U_ZERO_ERROR;
  const icu::Locale locale = icu::Locale::forLanguageTag(
      icu::StringPiece(bcp47_tag.data(), static_cast<int32_t>(bcp47_tag.size())), status);
  std::string terminology = U_SUCCESS(status) ? locale.getISO3Language() : "";
  // "und": undetermined, ISO 639-2's code for a language it cannot name.
  if (terminology.size() != 3) terminology = "und";
  Iso639 codes{terminology, terminology};
  for (const auto& [t, b] : kBibliographic) {
    if (terminology == t) codes.bibliographic = std::string(b);
  }
  return codes;
}

}  // namespace collide::text
