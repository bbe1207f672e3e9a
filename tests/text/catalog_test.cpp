// Compiled catalogues and plural rules: the MO reader, the Plural-Forms evaluator against the
// CLDR plural categories of Arabic, Polish, Russian and English, and the placeholder check.
#include "text/catalog.hpp"

#include <gtest/gtest.h>

#include <map>
#include <optional>
#include <stdexcept>
#include <string>

#include "catalog_check.hpp"
#include "text/embedded_catalogs.hpp"
#include "text/language.hpp"
#include "text/translate.hpp"

namespace collide::text {
namespace detail {
std::span<const EmbeddedCatalog> testCatalogs();  // tests/text/catalogs/*.po, compiled by msgfmt
}
namespace {

Catalog testCatalog(std::string_view tag) {
  for (const detail::EmbeddedCatalog& embedded : detail::testCatalogs()) {
    if (embedded.tag == tag) return Catalog::fromMo(embedded.mo_bytes);
  }
  throw std::logic_error("no test catalogue " + std::string(tag));
}

// The test catalogues name each plural form by its CLDR category: "few {count}".
std::string categoryFor(const Catalog& catalog, unsigned long n) {
  const std::vector<std::string>* forms = catalog.findPlural("", "{count} collision");
  EXPECT_NE(forms, nullptr);
  if (forms == nullptr) return "";
  const std::string& form = forms->at(static_cast<std::size_t>(catalog.pluralRule().formFor(n)));
  return form.substr(0, form.find(' '));
}

// The counts the issue names, with their categories from the CLDR plural rules charts
// (unicode.org/cldr/charts/latest/supplemental/language_plural_rules.html).
const unsigned long kCounts[] = {0, 1, 2, 5, 11, 21, 101};

TEST(PluralRuleTest, ArabicHasSixFormsChosenByCldrCategory) {
  const Catalog arabic = testCatalog("ar");
  EXPECT_EQ(arabic.pluralRule().forms(), 6);
  const std::map<unsigned long, std::string> cldr = {
      {0, "zero"}, {1, "one"}, {2, "two"}, {5, "few"}, {11, "many"}, {21, "many"}, {101, "other"}};
  for (unsigned long n : kCounts) EXPECT_EQ(categoryFor(arabic, n), cldr.at(n)) << "n = " << n;
  EXPECT_EQ(categoryFor(arabic, 103), "few");    // n % 100 in 3..10
  EXPECT_EQ(categoryFor(arabic, 100), "other");  // n % 100 in 0..2, n > 2
}

TEST(PluralRuleTest, PolishHasThreeForms) {
  const Catalog polish = testCatalog("pl");
  EXPECT_EQ(polish.pluralRule().forms(), 3);
  const std::map<unsigned long, std::string> cldr = {
      {0, "many"}, {1, "one"}, {2, "few"}, {5, "many"}, {11, "many"}, {21, "many"}, {101, "many"}};
  for (unsigned long n : kCounts) EXPECT_EQ(categoryFor(polish, n), cldr.at(n)) << "n = " << n;
  EXPECT_EQ(categoryFor(polish, 22), "few");
  EXPECT_EQ(categoryFor(polish, 12), "many");
}

TEST(PluralRuleTest, RussianHasThreeForms) {
  const Catalog russian = testCatalog("ru");
  EXPECT_EQ(russian.pluralRule().forms(), 3);
  const std::map<unsigned long, std::string> cldr = {
      {0, "many"}, {1, "one"}, {2, "few"}, {5, "many"}, {11, "many"}, {21, "one"}, {101, "one"}};
  for (unsigned long n : kCounts) EXPECT_EQ(categoryFor(russian, n), cldr.at(n)) << "n = " << n;
  EXPECT_EQ(categoryFor(russian, 111), "many");
  EXPECT_EQ(categoryFor(russian, 24), "few");
}

TEST(PluralRuleTest, EnglishUsesTheSingularForOneOnly) {
  const ScopedLanguage english("en");
  for (unsigned long n : kCounts) {
    EXPECT_EQ(trn("{count} collision", "{count} collisions", n),
              n == 1 ? "{count} collision" : "{count} collisions")
        << "n = " << n;
  }
}

TEST(PluralRuleTest, ParsesTheCOperatorsGettextAllows) {
  const PluralRule rule = PluralRule::parse(
      "nplurals=4; plural=!(n < 3) && n <= 10 ? 3 : n >= 2 ? (n*2-2)/2 : n % 2 + 0 == 1 ? 1 : 0;");
  EXPECT_EQ(rule.forms(), 4);
  EXPECT_EQ(rule.formFor(0), 0);
  EXPECT_EQ(rule.formFor(1), 1);
  EXPECT_EQ(rule.formFor(2), 1);   // (2*2-2)/2
  EXPECT_EQ(rule.formFor(5), 3);   // not below 3 and at most 10
  EXPECT_EQ(rule.formFor(11), 0);  // (22-2)/2 = 10 is no form: the first
}

TEST(PluralRuleTest, RejectsMalformedHeadersWithTheReason) {
  for (const char* header :
       {"nplurals=2; plural=(n != 1;", "nplurals=2;", "plural=n != 1;", "nplurals=0; plural=0;",
        "nplurals=2; plural=n ? 1;", "nplurals=2; plural=x;", "nplurals=x; plural=0;"}) {
    EXPECT_THROW(PluralRule::parse(header), std::invalid_argument) << header;
  }
  EXPECT_THROW(PluralRule::parse("nplurals=2; plural=" + std::string(200, '(') + "n" +
                                 std::string(200, ')') + ";"),
               std::invalid_argument);
  // Division by zero in a header is not a crash: the first form.
  EXPECT_EQ(PluralRule::parse("nplurals=2; plural=n / 0 + n % 0;").formFor(7), 0);
}

TEST(CatalogTest, RejectsBytesThatAreNoCatalogue) {
  const std::uint8_t garbage[40] = {1, 2, 3};
  EXPECT_THROW(Catalog::fromMo(garbage), std::invalid_argument);
  EXPECT_THROW(Catalog::fromMo(std::span<const std::uint8_t>()), std::invalid_argument);
  // A valid header whose string table points past the end.
  std::uint8_t truncated[28] = {0xde, 0x12, 0x04, 0x95, 0, 0, 0, 0, 1, 0, 0, 0, 28, 0,
                                0,    0,    36,   0,    0, 0, 0, 0, 0, 0, 0, 0, 0,  0};
  EXPECT_THROW(Catalog::fromMo(truncated), std::invalid_argument);
}

TEST(CatalogTest, KeepsContextsApart) {
  const Catalog bad = testCatalog("xx-Bad");
  ASSERT_NE(bad.find("energy part", "lost"), nullptr);
  EXPECT_EQ(*bad.find("energy part", "lost"), "verloren");
  ASSERT_NE(bad.find("", "lost"), nullptr);
  EXPECT_EQ(*bad.find("", "lost"), "Verlust");
  EXPECT_EQ(bad.find("", "not in it"), nullptr);
  EXPECT_EQ(bad.header("Language"), "xx");
}

TEST(CatalogueCheckTest, FindsPlaceholdersThatDifferFromTheOriginal) {
  const std::vector<std::string> problems = placeholderProblems(testCatalog("xx-Bad"));
  ASSERT_EQ(problems.size(), 2u) << ::testing::PrintToString(problems);
  EXPECT_EQ(problems[0],
            "msgid '{count} wall': plural form 1 names {count}, {extra}, the original {count} "
            "(only {count} may be left out)");
  EXPECT_EQ(problems[1],
            "msgid '{mass} at {speed}': translation names {masse}, {speed}, the original "
            "{mass}, {speed}");
  // Reordered placeholders and a form without {count} ("eine Wand") are right.
}

// The one-message reader (a language's own name in the list of all of them) finds what the
// parsed catalogue finds, for every message of every shipped catalogue, and nothing for a
// message that is not there.
TEST(CatalogTest, ReadingOneMessageFromTheBytesAgreesWithTheParsedCatalogue) {
  for (const detail::EmbeddedCatalog& embedded : detail::embeddedCatalogs()) {
    const Catalog catalog = Catalog::fromMo(embedded.mo_bytes);
    ASSERT_FALSE(catalog.entries().empty()) << embedded.tag;
    for (const Catalog::Entry& entry : catalog.entries()) {
      if (!entry.msgid_plural.empty()) continue;
      const std::string* parsed = catalog.find(entry.context, entry.msgid);
      const std::optional<std::string> read =
          Catalog::findInMo(embedded.mo_bytes, entry.context, entry.msgid);
      ASSERT_EQ(read.has_value(), parsed != nullptr) << embedded.tag << ": " << entry.msgid;
      if (parsed != nullptr) {
        EXPECT_EQ(*read, *parsed) << embedded.tag << ": " << entry.msgid;
      }
    }
    EXPECT_FALSE(Catalog::findInMo(embedded.mo_bytes, "", "no such message in any catalogue"));
    // The context is part of the key: "English" alone is not the language-name message.
    EXPECT_TRUE(Catalog::findInMo(embedded.mo_bytes, "language name", "English")) << embedded.tag;
    EXPECT_FALSE(Catalog::findInMo(embedded.mo_bytes, "", "English")) << embedded.tag;
  }
  const std::uint8_t not_mo[32] = {1, 2, 3};
  EXPECT_THROW(Catalog::findInMo(not_mo, "", "x"), std::invalid_argument);
}

TEST(CatalogueCheckTest, EveryShippedCatalogueKeepsThePlaceholders) {
  ASSERT_FALSE(detail::embeddedCatalogs().empty());
  for (const detail::EmbeddedCatalog& embedded : detail::embeddedCatalogs()) {
    const Catalog catalog = Catalog::fromMo(embedded.mo_bytes);
    EXPECT_EQ(placeholderProblems(catalog), std::vector<std::string>()) << embedded.tag;
    EXPECT_TRUE(catalog.header("Plural-Forms").has_value()) << embedded.tag;
    for (const Catalog::Entry& entry : catalog.entries()) {
      if (entry.msgid_plural.empty()) continue;
      EXPECT_EQ(entry.msgstrs.size(), static_cast<std::size_t>(catalog.pluralRule().forms()))
          << embedded.tag << ": " << entry.msgid;
    }
  }
}

// Where a shipped catalogue of these languages exists, its Plural-Forms header picks the CLDR
// category for each count the issue names (the test catalogues above show the mechanism).
TEST(CatalogueCheckTest, ShippedPluralRulesFollowCldr) {
  const std::map<std::string, std::map<unsigned long, int>> forms = {
      {"ar", {{0, 0}, {1, 1}, {2, 2}, {5, 3}, {11, 4}, {21, 4}, {101, 5}}},
      {"pl", {{0, 2}, {1, 0}, {2, 1}, {5, 2}, {11, 2}, {21, 2}, {101, 2}}},
      {"ru", {{0, 2}, {1, 0}, {2, 1}, {5, 2}, {11, 2}, {21, 0}, {101, 0}}},
      {"de", {{0, 1}, {1, 0}, {2, 1}, {5, 1}, {11, 1}, {21, 1}, {101, 1}}}};
  for (const Language& language : shippedLanguages()) {
    const auto expected = forms.find(language.tag);
    if (expected == forms.end() || language.catalog() == nullptr) continue;
    for (const auto& [n, form] : expected->second) {
      EXPECT_EQ(language.catalog()->pluralRule().formFor(n), form) << language.tag << " n = " << n;
    }
  }
}

}  // namespace
}  // namespace collide::text
