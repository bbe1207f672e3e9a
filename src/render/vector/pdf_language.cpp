#include "render/vector/pdf_language.hpp"

#include <cstdio>
#include <string_view>

#include "core/error.hpp"
#include "render/gl_context.hpp"

namespace collide::render {
namespace {

[[noreturn]] void unreadable(const char* what) {
  throw RenderError(std::string("PDF language: Cairo's file has no readable ") + what);
}

// The unsigned number after `key` (and white space) in `text`, from `from` on.
std::size_t numberAfter(std::string_view text, std::string_view key, std::size_t from = 0) {
  std::size_t at = text.find(key, from);
  if (at == std::string_view::npos) unreadable(key.data());
  at += key.size();
  while (at < text.size() && (text[at] == ' ' || text[at] == '\n' || text[at] == '\r')) ++at;
  std::size_t value = 0, digits = 0;
  for (; at < text.size() && text[at] >= '0' && text[at] <= '9'; ++at, ++digits) {
    value = 10 * value + static_cast<std::size_t>(text[at] - '0');
  }
  if (digits == 0) unreadable(key.data());
  return value;
}

// The contents of the dictionary that starts at `open` ("<<"), without its brackets; nested
// dictionaries and literal strings are skipped whole.
std::string_view dictionaryBody(std::string_view text, std::size_t open) {
  if (open == std::string_view::npos || text.compare(open, 2, "<<") != 0) unreadable("dictionary");
  int depth = 0, parens = 0;
  for (std::size_t at = open; at + 1 < text.size(); ++at) {
    const char c = text[at];
    if (parens > 0) {
      if (c == '\\')
        ++at;
      else if (c == '(')
        ++parens;
      else if (c == ')')
        --parens;
    } else if (c == '(') {
      parens = 1;
    } else if (text.compare(at, 2, "<<") == 0) {
      ++depth;
      ++at;
    } else if (text.compare(at, 2, ">>") == 0) {
      if (--depth == 0) return text.substr(open + 2, at - open - 2);
      ++at;
    }
  }
  unreadable("dictionary end");
}

// A PDF literal string: (text) with its backslashes and parentheses escaped.
std::string literal(const std::string& text) {
  std::string out = "(";
  for (const char c : text) {
    if (c == '\\' || c == '(' || c == ')') out += '\\';
    out += c;
  }
  return out + ")";
}

}  // namespace

std::string declarePdfLanguage(std::string pdf, const std::string& bcp47_tag) {
  if (bcp47_tag.empty()) return pdf;
  const std::string_view file(pdf);
  // The last revision: "startxref <offset>" near the end, the trailer after its table.
  const std::size_t startxref = file.rfind("startxref");
  if (startxref == std::string_view::npos) unreadable("startxref");
  const std::size_t xref_at = numberAfter(file, "startxref", startxref);
  if (file.compare(xref_at, 4, "xref") != 0) unreadable("cross-reference table");
  const std::size_t trailer = file.find("trailer", xref_at);
  if (trailer == std::string_view::npos) unreadable("trailer");
  const std::string_view trailer_body = dictionaryBody(file, file.find("<<", trailer));
  const std::size_t root = numberAfter(trailer_body, "/Root");
  if (trailer_body.find("/Prev") != std::string_view::npos) unreadable("single revision");
  // The catalogue's offset from the table's one subsection ("0 <size>", 20-byte entries).
  const std::size_t first = numberAfter(file, "xref", xref_at);
  const std::size_t count = numberAfter(file, std::to_string(first), xref_at + 4);
  if (root < first || root >= first + count) unreadable("catalogue entry");
  std::size_t entries = file.find('\n', file.find(std::to_string(first), xref_at + 4));
  if (entries == std::string_view::npos) unreadable("cross-reference entries");
  ++entries;
  const std::size_t entry = entries + 20 * (root - first);
  const std::size_t catalogue_at = numberAfter(file.substr(entry, 10), "");
  const std::string object = std::to_string(root) + " 0 obj";
  if (file.compare(catalogue_at, object.size(), object) != 0) unreadable("catalogue object");
  const std::string_view catalogue = dictionaryBody(file, file.find("<<", catalogue_at));
  if (catalogue.find("/Type /Catalog") == std::string_view::npos) unreadable("catalogue");

  std::string update;
  if (!pdf.ends_with('\n')) update += '\n';
  const std::size_t new_object_at = pdf.size() + update.size();
  update += object + "\n<<" + std::string(catalogue) + "   /Lang " + literal(bcp47_tag) +
            "\n>>\nendobj\n";
  const std::size_t new_xref_at = pdf.size() + update.size();
  char offset[32];
  std::snprintf(offset, sizeof offset, "%010zu 00000 n \n", new_object_at);
  update += "xref\n" + std::to_string(root) + " 1\n" + offset;
  update += "trailer\n<<" + std::string(trailer_body) + "   /Prev " + std::to_string(xref_at) +
            "\n>>\nstartxref\n" + std::to_string(new_xref_at) + "\n%%EOF\n";
  pdf += update;
  return pdf;
}

}  // namespace collide::render
