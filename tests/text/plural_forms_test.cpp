// Plural forms of the shipped catalogues for the counts the issue names (0, 1, 2, 5, 11, 21, 101
// collisions), in English, Polish, Russian and Arabic. The expected form comes from each
// language's CLDR plural rule, written here as CLDR states it (operands: i the integer, v the
// number of visible fraction digits, 0 for a count); the catalogue's Plural-Forms header must
// pick the message written for that category.
#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "text/catalog.hpp"
#include "text/language.hpp"
#include "text/plural_rule.hpp"
#include "text/translate.hpp"

namespace collide::text {
namespace {

const unsigned long kIssueCounts[] = {0, 1, 2, 5, 11, 21, 101};

bool within(unsigned long x, unsigned long low, unsigned long high) {
  return x >= low && x <= high;
}

// CLDR plural rules (unicode.org/cldr/charts/latest/supplemental/language_plural_rules.html),
// for whole counts (v = 0).
std::string englishCategory(unsigned long i) {
  return i == 1 ? "one" : "other";
}

std::string polishCategory(unsigned long i) {
  if (i == 1) return "one";
  if (within(i % 10, 2, 4) && !within(i % 100, 12, 14)) return "few";
  return "many";  // i != 1 and i % 10 in 0..1, or i % 10 in 5..9, or i % 100 in 12..14
}

std::string russianCategory(unsigned long i) {
  if (i % 10 == 1 && i % 100 != 11) return "one";
  if (within(i % 10, 2, 4) && !within(i % 100, 12, 14)) return "few";
  return "many";  // i % 10 = 0, or i % 10 in 5..9, or i % 100 in 11..14
}

std::string arabicCategory(unsigned long n) {
  if (n == 0) return "zero";
  if (n == 1) return "one";
  if (n == 2) return "two";
  if (within(n % 100, 3, 10)) return "few";
  if (within(n % 100, 11, 99)) return "many";
  return "other";
}

// The message "End, {time}: {count} collision." in each language, by category, as its
// translator wrote it for that category.
struct Expected {
  const char* tag;
  std::string (*category)(unsigned long);
  std::map<std::string, std::string> message;
};

const std::vector<Expected>& expectations() {
  static const std::vector<Expected> all = {
      {"en",
       englishCategory,
       {{"one", "End, {time}: {count} collision."}, {"other", "End, {time}: {count} collisions."}}},
      {"pl",
       polishCategory,
       {{"one", "Koniec, {time}: {count} zderzenie."},
        {"few", "Koniec, {time}: {count} zderzenia."},
        {"many", "Koniec, {time}: {count} zderzeń."}}},
      {"ru",
       russianCategory,
       {{"one", "Конец, {time}: {count} удар."},
        {"few", "Конец, {time}: {count} удара."},
        {"many", "Конец, {time}: {count} ударов."}}},
      // One and two say the count in the word itself ("one collision", "two collisions").
      {"ar",
       arabicCategory,
       {{"zero", "النهاية، {time}: {count} تصادم."},
        {"one", "النهاية، {time}: تصادم واحد."},
        {"two", "النهاية، {time}: تصادمان."},
        {"few", "النهاية، {time}: {count} تصادمات."},
        {"many", "النهاية، {time}: {count} تصادمًا."},
        {"other", "النهاية، {time}: {count} تصادم."}}},
  };
  return all;
}

bool isShipped(const std::string& tag) {
  for (const Language& language : shippedLanguages()) {
    if (language.tag == tag) return true;
  }
  return false;
}

TEST(PluralFormsTest, EachCountTakesTheFormOfItsCldrCategory) {
  int checked_languages = 0;
  for (const Expected& language : expectations()) {
    if (!isShipped(language.tag)) continue;  // Arabic until its catalogue ships: the next test
    ++checked_languages;
    const ScopedLanguage scope(language.tag);
    for (unsigned long n : kIssueCounts) {
      EXPECT_EQ(trn("End, {time}: {count} collision.", "End, {time}: {count} collisions.", n),
                language.message.at(language.category(n)))
          << language.tag << ", n = " << n << " (" << language.category(n) << ")";
    }
  }
  EXPECT_GE(checked_languages, 3);  // en, pl and ru ship
}

// gettext numbers the forms in the order of CLDR's categories (zero, one, two, few, many,
// other, those the language has). Arabic's rule, from its shipped catalogue, or, while that has
// not shipped, the Plural-Forms header its catalogue uses (gettext's for Arabic).
TEST(PluralFormsTest, ArabicsRuleChoosesTheCldrCategoryForEveryCount) {
  const std::vector<std::string> order = {"zero", "one", "two", "few", "many", "other"};
  PluralRule parsed;
  const PluralRule* rule = nullptr;
  for (const Language& language : shippedLanguages()) {
    if (language.tag == "ar" && language.catalog() != nullptr)
      rule = &language.catalog()->pluralRule();
  }
  if (rule == nullptr) {
    parsed = PluralRule::parse(
        "nplurals=6; plural=(n==0 ? 0 : n==1 ? 1 : n==2 ? 2 : n%100>=3 && n%100<=10 ? 3 : "
        "n%100>=11 ? 4 : 5);");
    rule = &parsed;
  }
  ASSERT_EQ(rule->forms(), 6);
  std::vector<unsigned long> counts(std::begin(kIssueCounts), std::end(kIssueCounts));
  for (unsigned long n : {3ul, 10ul, 99ul, 100ul, 102ul, 103ul, 111ul, 1000ul}) counts.push_back(n);
  for (unsigned long n : counts) {
    const std::string category = arabicCategory(n);
    const auto index = std::find(order.begin(), order.end(), category) - order.begin();
    EXPECT_EQ(rule->formFor(n), index) << "n = " << n << " (" << category << ")";
  }
}

}  // namespace
}  // namespace collide::text
