#include "text/catalog.hpp"

#include <stdexcept>

namespace collide::text {
namespace {

constexpr std::uint32_t kMagic = 0x950412de;
constexpr char kContextEnd = '\x04';  // msgfmt joins context and msgid with EOT

class MoReader {
 public:
  explicit MoReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {
    if (bytes.size() < 28) fail("shorter than an MO header");
    const std::uint32_t magic = word(0);
    if (magic == kMagic) {
      swapped_ = false;
    } else if (swap(magic) == kMagic) {
      swapped_ = true;
    } else {
      fail("not an MO file (magic number)");
    }
    if (word(4) >> 16 > 1) fail("unknown major revision");
  }

  std::uint32_t count() const { return word(8); }
  std::string_view original(std::uint32_t i) const { return string(word(12), i); }
  std::string_view translation(std::uint32_t i) const { return string(word(16), i); }

 private:
  [[noreturn]] static void fail(const std::string& what) {
    throw std::invalid_argument("message catalogue: " + what);
  }
  static std::uint32_t swap(std::uint32_t w) {
    return (w >> 24) | ((w >> 8) & 0xff00) | ((w << 8) & 0xff0000) | (w << 24);
  }
  std::uint32_t word(std::size_t offset) const {
    if (offset > bytes_.size() || bytes_.size() - offset < 4) fail("offset beyond the end");
    const std::uint32_t w = std::uint32_t(bytes_[offset]) | std::uint32_t(bytes_[offset + 1]) << 8 |
                            std::uint32_t(bytes_[offset + 2]) << 16 |
                            std::uint32_t(bytes_[offset + 3]) << 24;
    return swapped_ ? swap(w) : w;
  }
  // String i of the table at `table`: each entry is (length, offset).
  std::string_view string(std::uint32_t table, std::uint32_t i) const {
    const std::size_t entry = std::size_t(table) + 8 * std::size_t(i);
    const std::uint32_t length = word(entry);
    const std::uint32_t offset = word(entry + 4);
    if (offset > bytes_.size() || bytes_.size() - offset <= length) fail("string beyond the end");
    return {reinterpret_cast<const char*>(bytes_.data()) + offset, length};
  }

  std::span<const std::uint8_t> bytes_;
  bool swapped_ = false;
};

std::vector<std::string> splitAtNul(std::string_view text) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t nul = text.find('\0', start);
    parts.emplace_back(text.substr(start, nul == std::string_view::npos ? nul : nul - start));
    if (nul == std::string_view::npos) return parts;
    start = nul + 1;
  }
}

}  // namespace

std::string Catalog::key(std::string_view context, std::string_view msgid) {
  std::string k;
  if (!context.empty()) {
    k.append(context);
    k += kContextEnd;
  }
  k.append(msgid);
  return k;
}

Catalog Catalog::fromMo(std::span<const std::uint8_t> bytes) {
  const MoReader mo(bytes);
  Catalog catalog;
  const std::uint32_t n = mo.count();
  if (n > bytes.size() / 16) throw std::invalid_argument("message catalogue: too many entries");
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::string_view original = mo.original(i);
    if (original.empty()) {  // the header entry
      catalog.header_ = std::string(mo.translation(i));
      continue;
    }
    Entry entry;
    std::string_view id = original;
    if (const std::size_t eot = id.find(kContextEnd); eot != std::string_view::npos) {
      entry.context = std::string(id.substr(0, eot));
      id.remove_prefix(eot + 1);
    }
    const std::vector<std::string> ids = splitAtNul(id);
    entry.msgid = ids[0];
    if (ids.size() > 1) entry.msgid_plural = ids[1];
    entry.msgstrs = splitAtNul(mo.translation(i));
    catalog.index_[key(entry.context, entry.msgid)] = catalog.entries_.size();
    catalog.entries_.push_back(std::move(entry));
  }
  if (const std::optional<std::string> plural = catalog.header("Plural-Forms")) {
    catalog.plural_rule_ = PluralRule::parse(*plural);
  }
  return catalog;
}

std::optional<std::string> Catalog::findInMo(std::span<const std::uint8_t> bytes,
                                             std::string_view context, std::string_view msgid) {
  const MoReader mo(bytes);
  const std::string wanted = key(context, msgid);
  const std::uint32_t n = mo.count();
  if (n > bytes.size() / 16) throw std::invalid_argument("message catalogue: too many entries");
  for (std::uint32_t i = 0; i < n; ++i) {
    if (mo.original(i) != wanted) continue;
    const std::string_view translation = mo.translation(i);
    const std::string_view first = translation.substr(0, translation.find('\0'));
    if (first.empty()) return std::nullopt;
    return std::string(first);
  }
  return std::nullopt;
}

const std::string* Catalog::find(std::string_view context, std::string_view msgid) const {
  const auto it = index_.find(key(context, msgid));
  if (it == index_.end()) return nullptr;
  const Entry& entry = entries_[it->second];
  return entry.msgstrs.empty() || entry.msgstrs[0].empty() ? nullptr : &entry.msgstrs[0];
}

const std::vector<std::string>* Catalog::findPlural(std::string_view context,
                                                    std::string_view msgid) const {
  const auto it = index_.find(key(context, msgid));
  if (it == index_.end()) return nullptr;
  const Entry& entry = entries_[it->second];
  return entry.msgid_plural.empty() ? nullptr : &entry.msgstrs;
}

std::optional<std::string> Catalog::header(std::string_view name) const {
  std::size_t start = 0;
  while (start < header_.size()) {
    std::size_t end = header_.find('\n', start);
    if (end == std::string::npos) end = header_.size();
    const std::string_view line = std::string_view(header_).substr(start, end - start);
    if (line.size() > name.size() && line.substr(0, name.size()) == name &&
        line[name.size()] == ':') {
      std::string_view value = line.substr(name.size() + 1);
      while (!value.empty() && value.front() == ' ') value.remove_prefix(1);
      return std::string(value);
    }
    start = end + 1;
  }
  return std::nullopt;
}

}  // namespace collide::text
