// How each language writes a number, from CLDR through ICU (the Unicode consortium's locale data is
// what a reader's own computer uses; writing the table by hand would drift from it). Only the
// symbols come from CLDR; the rules of number_format.hpp (three figures, grouping from five
// digits, SI prefixes) are the same in every language.
#include <unicode/dcfmtsym.h>
#include <unicode/decimfmt.h>
#include <unicode/locid.h>
#include <unicode/numfmt.h>
#include <unicode/unistr.h>

#include <memory>
#include <utility>

#include "text/language.hpp"
#include "text/number_format.hpp"

namespace collide::text {
namespace {

constexpr std::string_view kTrueMinus = "\u2212";

std::string utf8(const icu::UnicodeString& text) {
  std::string out;
  text.toUTF8String(out);
  return out;
}

// CLDR writes the minus of most languages as the ASCII hyphen-minus (what a keyboard types); a
// picture sets the true minus sign U+2212 in its place, keeping any bidi mark around it (Arabic:
// U+061C before it).
std::string trueMinus(std::string minus) {
  const std::size_t hyphen = minus.find('-');
  if (hyphen != std::string::npos) minus.replace(hyphen, 1, kTrueMinus);
  return minus;
}

NumberStyle fromCldr(std::string_view tag) {
  NumberStyle style;
  UErrorCode status = U_ZERO_ERROR;
  const icu::Locale locale = icu::Locale::forLanguageTag(
      icu::StringPiece(tag.data(), static_cast<int32_t>(tag.size())), status);
  if (U_FAILURE(status)) return style;
  const icu::DecimalFormatSymbols symbols(locale, status);
  if (U_FAILURE(status)) return style;
  using Symbol = icu::DecimalFormatSymbols::ENumberFormatSymbol;
  const auto symbol = [&](Symbol which) { return utf8(symbols.getConstSymbol(which)); };
  style.decimal_separator = symbol(icu::DecimalFormatSymbols::kDecimalSeparatorSymbol);
  style.group_separator = symbol(icu::DecimalFormatSymbols::kGroupingSeparatorSymbol);
  style.minus = trueMinus(symbol(icu::DecimalFormatSymbols::kMinusSignSymbol));
  style.plus = symbol(icu::DecimalFormatSymbols::kPlusSignSymbol);
  const Symbol digit_symbols[] = {
      icu::DecimalFormatSymbols::kZeroDigitSymbol,  icu::DecimalFormatSymbols::kOneDigitSymbol,
      icu::DecimalFormatSymbols::kTwoDigitSymbol,   icu::DecimalFormatSymbols::kThreeDigitSymbol,
      icu::DecimalFormatSymbols::kFourDigitSymbol,  icu::DecimalFormatSymbols::kFiveDigitSymbol,
      icu::DecimalFormatSymbols::kSixDigitSymbol,   icu::DecimalFormatSymbols::kSevenDigitSymbol,
      icu::DecimalFormatSymbols::kEightDigitSymbol, icu::DecimalFormatSymbols::kNineDigitSymbol};
  for (Symbol digit : digit_symbols) style.digits.push_back(symbol(digit));
  if (style.digits.front() == "0") style.digits.clear();  // ASCII: nothing to replace

  // Group sizes and where the percent sign goes come from the language's patterns: format a
  // probe and read them off.
  std::unique_ptr<icu::NumberFormat> decimal(icu::NumberFormat::createInstance(locale, status));
  if (U_SUCCESS(status)) {
    if (const auto* pattern = dynamic_cast<const icu::DecimalFormat*>(decimal.get())) {
      if (pattern->getGroupingSize() > 0) style.group_size = pattern->getGroupingSize();
      style.secondary_group_size = pattern->getSecondaryGroupingSize() > 0
                                       ? pattern->getSecondaryGroupingSize()
                                       : style.group_size;
    }
  }
  status = U_ZERO_ERROR;
  std::unique_ptr<icu::NumberFormat> percent(
      icu::NumberFormat::createPercentInstance(locale, status));
  if (U_SUCCESS(status)) {
    icu::UnicodeString probe;
    percent->format(0.37, probe);  // "37%", "37 %", "%37", "٣٧٪؜"
    const std::string shown = utf8(probe);
    const std::string number = withLocalDigits("37", style);
    const std::size_t at = shown.find(number);
    if (at != std::string::npos) {
      style.percent_prefix = shown.substr(0, at);
      style.percent_suffix = shown.substr(at + number.size());
    }
  }
  if (style.decimal_separator == ",") style.list_separator = "; ";
  // The Arabic decimal sign (٫) is a small comma too: a vector's components are kept apart by
  // the Arabic semicolon, "(١٫٥؛ ٢)", never by a comma that reads as another decimal sign.
  if (style.decimal_separator == "\u066B") style.list_separator = "\u061B ";
  return style;
}

}  // namespace

NumberStyle numberStyleFor(std::string_view bcp47_tag) {
  return fromCldr(bcp47_tag);
}

const NumberStyle& numberStyle(const Language& language) {
  // One style per shipped language, read once (ICU's data lookups are not for every frame).
  static const std::vector<std::pair<const Language*, NumberStyle>> styles = [] {
    std::vector<std::pair<const Language*, NumberStyle>> all;
    for (const Language& shipped : shippedLanguages()) {
      // The pseudo-language tests layout with English conventions.
      all.emplace_back(&shipped, fromCldr(shipped.pseudo ? kSourceLanguage : shipped.tag));
    }
    return all;
  }();
  for (const auto& [shipped, style] : styles) {
    if (shipped == &language) return style;
  }
  return englishStyle();
}

const NumberStyle& englishStyle() {
  static const NumberStyle english;
  return english;
}

const NumberStyle& defaultStyle() {
  return numberStyle(activeLanguage());
}

std::string numberPair(std::string_view first, std::string_view second, const NumberStyle& style) {
  return "(" + std::string(first) + style.list_separator + std::string(second) + ")";
}

}  // namespace collide::text
