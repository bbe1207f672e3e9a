#pragma once
// One language's messages, read from a compiled gettext catalogue (the MO format msgfmt writes:
// https://www.gnu.org/software/gettext/manual/html_node/MO-Files.html). collide compiles po/*.po
// with msgfmt at build time and embeds the bytes (text/embedded_catalogs.hpp), so nothing is read
// from an install path.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "text/plural_rule.hpp"

namespace collide::text {

class Catalog {
 public:
  Catalog() = default;  // empty: every lookup misses (English, the source language)

  // Reads MO bytes (either byte order). Throws std::invalid_argument when they are not a
  // well-formed catalogue or the Plural-Forms header does not parse.
  static Catalog fromMo(std::span<const std::uint8_t> bytes);

  // The translation of one message without plural forms, read straight from MO bytes, without
  // building a catalogue (a language's own name for a list of every language); nullopt when absent
  // or empty. Throws like fromMo on bytes that are not a catalogue.
  static std::optional<std::string> findInMo(std::span<const std::uint8_t> bytes,
                                             std::string_view context, std::string_view msgid);

  // The translation of msgid in context (empty: none); nullptr when the catalogue has none.
  const std::string* find(std::string_view context, std::string_view msgid) const;
  // The plural forms of msgid (the singular msgid) in context; nullptr when absent.
  const std::vector<std::string>* findPlural(std::string_view context,
                                             std::string_view msgid) const;

  const PluralRule& pluralRule() const { return plural_rule_; }
  // A header field of the catalogue ("Language", "Plural-Forms"), if present.
  std::optional<std::string> header(std::string_view name) const;

  // Every entry (key: context + '\x04' + msgid, or msgid), for the catalogue checks.
  struct Entry {
    std::string context;
    std::string msgid;
    std::string msgid_plural;          // empty for a message without plural forms
    std::vector<std::string> msgstrs;  // one, or one per plural form
  };
  const std::vector<Entry>& entries() const { return entries_; }

 private:
  static std::string key(std::string_view context, std::string_view msgid);

  std::vector<Entry> entries_;
  std::unordered_map<std::string, std::size_t> index_;  // key -> entries_ position
  std::string header_;
  PluralRule plural_rule_;
};

}  // namespace collide::text
