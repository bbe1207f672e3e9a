#include "text/language.hpp"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <memory>
#include <mutex>
#include <optional>

#include "core/error.hpp"
#include "text/embedded_catalogs.hpp"
#include "text/translate.hpp"

namespace collide::text {
namespace detail {

// A mutex and an atomic pointer rather than std::call_once: call_once keeps its callable in
// thread-local storage, which would make collide-gl.so (it links this library) need the dynamic
// loader's __tls_get_addr.
struct CatalogSlot {
  std::span<const std::uint8_t> mo_bytes;
  std::mutex parsing;
  std::atomic<const Catalog*> parsed{nullptr};
  std::optional<Catalog> catalog;
};

}  // namespace detail
namespace {

// Scripts written from right to left, by primary language subtag.
bool rightToLeft(std::string_view primary) {
  for (std::string_view rtl : {"ar", "he", "fa", "ur", "ps", "yi", "dv", "ckb", "sd", "ug"}) {
    if (primary == rtl) return true;
  }
  return false;
}

// Case as BCP 47 writes it: language lower, script title case, region upper.
std::string canonical(std::string_view tag) {
  std::string out;
  std::size_t start = 0;
  bool first = true;
  while (start <= tag.size()) {
    std::size_t end = tag.find_first_of("-_", start);
    if (end == std::string_view::npos) end = tag.size();
    std::string part(tag.substr(start, end - start));
    for (char& c : part) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (!first && part.size() == 4) {
      part[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(part[0])));
    } else if (!first && part.size() == 2) {
      for (char& c : part) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
    out += (first ? "" : "-") + part;
    first = false;
    start = end + 1;
  }
  return out;
}

bool wellFormed(std::string_view tag) {
  if (tag.empty() || tag.size() > 35) return false;
  std::size_t start = 0;
  while (start <= tag.size()) {
    std::size_t end = tag.find_first_of("-_", start);
    if (end == std::string_view::npos) end = tag.size();
    const std::size_t length = end - start;
    if (length < 1 || length > 8) return false;
    for (std::size_t i = start; i < end; ++i) {
      if (!std::isalnum(static_cast<unsigned char>(tag[i]))) return false;
    }
    if (start == 0 && (length < 2 || length > 3)) return false;
    start = end + 1;
  }
  return true;
}

std::string primaryOf(std::string_view tag) {
  return std::string(tag.substr(0, tag.find('-')));
}

struct Registry {
  std::vector<std::unique_ptr<detail::CatalogSlot>> slots;
  std::vector<Language> languages;

  Registry() {
    languages.push_back({std::string(kSourceLanguage), nullptr, false, false});
    for (const detail::EmbeddedCatalog& embedded : detail::embeddedCatalogs()) {
      slots.push_back(std::make_unique<detail::CatalogSlot>());
      slots.back()->mo_bytes = embedded.mo_bytes;
      const std::string tag(embedded.tag);
      languages.push_back({tag, slots.back().get(), false, rightToLeft(primaryOf(tag))});
    }
    languages.push_back({std::string(kPseudoLanguage), nullptr, true, false});
  }
};

const Registry& registry() {
  static const Registry shipped;
  return shipped;
}

std::atomic<const Language*> active{nullptr};

const Language* exactly(std::string_view tag) {
  for (const Language& language : registry().languages) {
    if (language.tag == tag) return &language;
  }
  return nullptr;
}

}  // namespace

const Catalog* Language::catalog() const {
  if (slot == nullptr) return nullptr;
  if (const Catalog* done = slot->parsed.load(std::memory_order_acquire)) return done;
  const std::lock_guard<std::mutex> lock(slot->parsing);
  if (!slot->catalog) slot->catalog.emplace(Catalog::fromMo(slot->mo_bytes));
  slot->parsed.store(&*slot->catalog, std::memory_order_release);
  return &*slot->catalog;
}

const std::vector<Language>& shippedLanguages() {
  return registry().languages;
}

std::string languageName(const Language& language) {
  if (language.pseudo) return "pseudo-language";
  if (language.slot != nullptr) {
    // TRANSLATORS: the name of your language, written in it ("Deutsch", "Français", "العربية").
    static constexpr const char* kEnglish = NC_("language name", "English");
    // Read from the catalogue's bytes: the list of every language (in --help) parses none.
    if (std::optional<std::string> name =
            Catalog::findInMo(language.slot->mo_bytes, "language name", kEnglish)) {
      return *name;
    }
    return language.tag;
  }
  return "English";
}

std::string shippedLanguageList() {
  std::string list;
  for (const Language& language : shippedLanguages()) {
    list += (list.empty() ? "" : ", ") + language.tag + " (" + languageName(language) + ")";
  }
  return list;
}

const Language& findLanguage(std::string_view tag, std::string_view typed_by) {
  const auto unknown = [&](const std::string& why) -> core::InputError {
    return core::InputError(std::string(typed_by) + " '" + std::string(tag) + "': " + why +
                            "; shipped languages: " + shippedLanguageList());
  };
  if (!wellFormed(tag)) throw unknown("not a BCP 47 language tag such as de, pt-BR or zh-Hans");
  std::string wanted = canonical(tag);
  // Chinese by region means a script: mainland and Singapore write Simplified, the rest
  // Traditional.
  for (const auto& [region, script] : {std::pair{"zh-CN", "zh-Hans"},
                                       {"zh-SG", "zh-Hans"},
                                       {"zh-TW", "zh-Hant"},
                                       {"zh-HK", "zh-Hant"},
                                       {"zh-MO", "zh-Hant"},
                                       {"zh", "zh-Hans"}}) {
    if (wanted == region) wanted = script;
  }
  // RFC 4647 lookup: drop subtags from the end until a shipped tag matches.
  for (std::string candidate = wanted;;) {
    if (const Language* language = exactly(candidate)) return *language;
    const std::size_t dash = candidate.rfind('-');
    if (dash == std::string::npos) break;
    candidate.resize(dash);
  }
  // Then any shipped variant of the same language (pt -> pt-BR).
  const std::string primary = primaryOf(wanted);
  for (const Language& language : shippedLanguages()) {
    if (!language.pseudo && primaryOf(language.tag) == primary) return language;
  }
  throw unknown("not a shipped language");
}

const Language& activeLanguage() {
  const Language* language = active.load(std::memory_order_acquire);
  return language != nullptr ? *language : shippedLanguages().front();
}

void setActiveLanguage(const Language& language) {
  active.store(&language, std::memory_order_release);
}

ScopedLanguage::ScopedLanguage(std::string_view tag) : previous_(&activeLanguage()) {
  setActiveLanguage(findLanguage(tag));
}

ScopedLanguage::~ScopedLanguage() {
  setActiveLanguage(*previous_);
}

}  // namespace collide::text
