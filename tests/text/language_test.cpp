// Choosing a language by BCP 47 tag, translating through the shipped catalogues, placeholders
// and the pseudo-language.
#include "text/language.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include "core/error.hpp"
#include "text/translate.hpp"
#include "text/wording.hpp"

namespace collide::text {
namespace {

std::size_t codePoints(const std::string& text) {
  std::size_t count = 0;
  for (char c : text) count += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  return count;
}

TEST(LanguageTest, FindsShippedLanguagesWhateverTheCaseOrSeparator) {
  for (const char* typed : {"de", "DE", "de-AT", "de_DE", "de-Latn-CH"}) {
    EXPECT_EQ(findLanguage(typed).tag, "de") << typed;
  }
  EXPECT_EQ(findLanguage("en-GB").tag, "en");
  EXPECT_EQ(findLanguage("en-xa").tag, "en-XA");
  EXPECT_TRUE(findLanguage("en-XA").pseudo);
  EXPECT_EQ(shippedLanguages().front().tag, "en");
  EXPECT_EQ(shippedLanguages().back().tag, "en-XA");
}

TEST(LanguageTest, AnUnknownTagNamesWhatWasTypedAndTheShippedLanguages) {
  try {
    findLanguage("tlh", "--lang");
    FAIL() << "no exception";
  } catch (const core::InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("--lang 'tlh': not a shipped language"), std::string::npos) << message;
    EXPECT_NE(message.find("shipped languages: en (English), ar (العربية), de (Deutsch)"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("ja (日本語)"), std::string::npos) << message;
    EXPECT_NE(message.find("en-XA (pseudo-language)"), std::string::npos) << message;
  }
  for (const char* malformed : {"", "d", "de--AT", "de-", "toolonglanguage", "de AT", "é"}) {
    EXPECT_THROW(findLanguage(malformed), core::InputError) << malformed;
  }
}

TEST(LanguageTest, RightToLeftComesFromTheLanguage) {
  EXPECT_FALSE(findLanguage("de").right_to_left);
  EXPECT_FALSE(findLanguage("en").right_to_left);
  EXPECT_TRUE(findLanguage("ar").right_to_left);
  EXPECT_FALSE(findLanguage("hi").right_to_left);
  EXPECT_EQ(findLanguage("zh-CN").tag, "zh-Hans");
}

// A catalogue is parsed when first asked for, once: threads asking at the same time for the
// same language all get that one catalogue.
TEST(LanguageTest, EachLanguageHasOneCatalogueWhoeverAsksFirst) {
  for (const Language& language : shippedLanguages()) {
    if (language.tag == kSourceLanguage || language.pseudo) {
      EXPECT_EQ(language.catalog(), nullptr) << language.tag;
      continue;
    }
    std::vector<const Catalog*> seen(4, nullptr);
    std::vector<std::thread> threads;
    for (std::size_t i = 0; i < seen.size(); ++i) {
      threads.emplace_back([&, i] { seen[i] = language.catalog(); });
    }
    for (std::thread& thread : threads) thread.join();
    ASSERT_NE(seen[0], nullptr) << language.tag;
    for (const Catalog* catalog : seen) EXPECT_EQ(catalog, seen[0]) << language.tag;
    EXPECT_EQ(language.catalog(), seen[0]) << language.tag;
    // Its own name, read without the catalogue, is the catalogue's.
    const std::string* name = seen[0]->find("language name", "English");
    ASSERT_NE(name, nullptr) << language.tag;
    EXPECT_EQ(languageName(language), *name);
  }
}

TEST(TranslateTest, TheShippedGermanCatalogueIsEmbeddedAndUsed) {
  const ScopedLanguage german("de");
  EXPECT_EQ(tr("Energy against time"), "Energie über der Zeit");
  EXPECT_EQ(trc("energy part", "lost"), "verloren");
  EXPECT_EQ(fill(trn("{count} collision has happened so far.",
                     "{count} collisions have happened so far.", 2),
                 {{"count", "2"}}),
            "Bisher gab es 2 Stöße.");
  EXPECT_EQ(symbol(Symbol::kKineticEnergy), "Ekin");
  EXPECT_EQ(listWithAnd({"a", "b", "c"}), "a, b und c");
  // A message no catalogue has stays English.
  EXPECT_EQ(tr("not a message of collide"), "not a message of collide");
}

TEST(TranslateTest, ScopedLanguageRestoresTheLanguageBefore) {
  {
    const ScopedLanguage german("de");
    EXPECT_EQ(activeLanguage().tag, "de");
  }
  EXPECT_EQ(activeLanguage().tag, "en");
  EXPECT_EQ(tr("Energy against time"), "Energy against time");
  EXPECT_EQ(listWithAnd({"a", "b"}), "a and b");
  EXPECT_EQ(listWithAnd({"a"}), "a");
}

TEST(WordingTest, ASentenceStartsWithACapitalAsItsLanguageWritesIt) {
  EXPECT_EQ(sentenceStart("cart 1 (1 kg) is at x = 0.22 m."), "Cart 1 (1 kg) is at x = 0.22 m.");
  EXPECT_EQ(sentenceStart("\u00e9lan"), "\u00c9lan");  // é -> É, two bytes each
  EXPECT_EQ(sentenceStart("\u0448\u0430\u0440 1"), "\u0428\u0430\u0440 1");  // Cyrillic ш -> Ш
  EXPECT_EQ(sentenceStart("Cart 1"), "Cart 1");
  EXPECT_EQ(sentenceStart("2 blocks"), "2 blocks");
  EXPECT_EQ(sentenceStart("\u5c0f\u8f66 1"), "\u5c0f\u8f66 1");  // Han has no case
  EXPECT_EQ(sentenceStart(""), "");
  {
    const ScopedLanguage turkish("tr");
    EXPECT_EQ(sentenceStart("istasyon"), "\u0130stasyon");  // Turkish dotted capital İ
  }
  EXPECT_EQ(sentenceStart("istasyon"), "Istasyon");
}

TEST(TranslateTest, FillReplacesNamedPlaceholdersInAnyOrder) {
  EXPECT_EQ(fill("{b} und {a}, {a}", {{"a", "1"}, {"b", "2"}}), "2 und 1, 1");
  EXPECT_EQ(fill("{unknown} {} {a b} {", {{"a", "1"}}), "{unknown} {} {a b} {");
  EXPECT_EQ(fill("e = {restitution}, {body.2.mass} kg", {{"body.2.mass", "3"}}),
            "e = {restitution}, 3 kg");
  EXPECT_EQ(placeholderNames("{mass} at {speed}, {} {mass}"),
            (std::vector<std::string>{"mass", "speed", "mass"}));
}

TEST(TranslateTest, PseudoLanguageIsFortyPercentLongerAccentedAndKeepsPlaceholders) {
  const ScopedLanguage pseudo("en-XA");
  for (const char* english :
       {"Energy against time", "lost", "{time}: energy lost {lost} of {total}",
        "An arrow on each moving body shows its velocity."}) {
    const std::string shown = tr(english);
    EXPECT_GE(codePoints(shown), std::ceil(1.4 * codePoints(english))) << shown;
    EXPECT_EQ(placeholderNames(shown), placeholderNames(english)) << shown;
    std::string outside = fill(shown, {{"time", ""}, {"lost", ""}, {"total", ""}});
    for (char c : outside) {
      EXPECT_FALSE((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z')) << shown;
    }
  }
  EXPECT_EQ(trn("{count} wall", "{count} walls", 1), pseudoTranslate("{count} wall"));
  EXPECT_EQ(trn("{count} wall", "{count} walls", 3), pseudoTranslate("{count} walls"));
}

}  // namespace
}  // namespace collide::text
