#include "scene/toml_guard.hpp"

#include <cstdint>
#include <cstdio>
#include <optional>

#include "scene/scene_desc.hpp"

namespace collide::scene::detail {
namespace {

enum class Lexeme { kCode, kComment, kBasic, kLiteral, kMultiBasic, kMultiLiteral };

struct Problem {
  int line = 0, column = 0;
  std::string what;
};

// Decodes one UTF-8 sequence at text[i]; returns its length, or 0 if it is not valid UTF-8.
std::size_t decodeUtf8(std::string_view text, std::size_t i, char32_t& code_point) {
  const unsigned char lead = static_cast<unsigned char>(text[i]);
  const std::size_t length = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC2 ? 2 : 0;
  if (length == 0 || lead > 0xF4 || i + length > text.size()) return 0;
  code_point = lead & (0x7F >> length);
  for (std::size_t k = 1; k < length; ++k) {
    const unsigned char next = static_cast<unsigned char>(text[i + k]);
    if ((next & 0xC0) != 0x80) return 0;
    code_point = (code_point << 6) | (next & 0x3F);
  }
  const char32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
  if (code_point < smallest[length] || code_point > 0x10FFFF ||
      (code_point >= 0xD800 && code_point <= 0xDFFF)) {
    return 0;
  }
  return length;
}

std::string escaped(char32_t code_point) {
  char text[16];
  if (code_point <= 0xFFFF) {
    std::snprintf(text, sizeof text, "\\u%04X", static_cast<unsigned>(code_point));
  } else {
    std::snprintf(text, sizeof text, "\\U%08X", static_cast<unsigned>(code_point));
  }
  return text;
}

class Rewriter {
 public:
  explicit Rewriter(std::string_view text) : text_(text) {}

  std::optional<Problem> run(std::string& out) {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") i_ = 3;  // byte order mark
    while (i_ < text_.size()) {
      const unsigned char c = static_cast<unsigned char>(text_[i_]);
      if (c >= 0x80) {
        if (std::optional<Problem> problem = nonAscii(out)) return problem;
        continue;
      }
      const std::size_t length = asciiStep();
      out.append(text_.substr(i_, length));
      advance(length);
    }
    return std::nullopt;
  }

 private:
  bool startsWith(std::string_view s) const { return text_.substr(i_, s.size()) == s; }

  void advance(std::size_t length) {
    for (std::size_t k = i_; k < i_ + length && k < text_.size(); ++k) {
      if (text_[k] == '\n') {
        ++line_, column_ = 1;
      } else if ((static_cast<unsigned char>(text_[k]) & 0xC0) != 0x80) {
        ++column_;
      }
    }
    i_ += length;
  }

  // A multi-line string may end in up to two extra quotes that belong to its content.
  std::size_t closingLength(char quote) const {
    const std::string_view five(quote == '"' ? "\"\"\"\"\"" : "'''''");
    for (std::size_t n = 5; n >= 3; --n) {
      if (startsWith(five.substr(0, n))) return n;
    }
    return 0;
  }

  // Moves the lexer state over one ASCII character (or escape/delimiter); returns bytes consumed.
  std::size_t asciiStep() {
    const char c = text_[i_];
    switch (state_) {
      case Lexeme::kCode:
        if (c == '#') {
          state_ = Lexeme::kComment;
        } else if (startsWith("\"\"\"")) {
          state_ = Lexeme::kMultiBasic;
          return 3;
        } else if (startsWith("'''")) {
          state_ = Lexeme::kMultiLiteral;
          return 3;
        } else if (c == '"') {
          state_ = Lexeme::kBasic;
        } else if (c == '\'') {
          state_ = Lexeme::kLiteral;
        }
        return 1;
      case Lexeme::kComment:
        if (c == '\n') state_ = Lexeme::kCode;
        return 1;
      case Lexeme::kBasic:
        if (c == '\\' && i_ + 1 < text_.size() && text_[i_ + 1] > 0 && text_[i_ + 1] != '\n') {
          return 2;
        }
        if (c == '"' || c == '\n') state_ = Lexeme::kCode;
        return 1;
      case Lexeme::kLiteral:
        if (c == '\'' || c == '\n') state_ = Lexeme::kCode;
        return 1;
      case Lexeme::kMultiBasic:
        if (c == '\\' && i_ + 1 < text_.size() && text_[i_ + 1] > 0) return 2;
        if (std::size_t n = closingLength('"'); n > 0) {
          state_ = Lexeme::kCode;
          return n;
        }
        return 1;
      case Lexeme::kMultiLiteral:
        if (std::size_t n = closingLength('\''); n > 0) {
          state_ = Lexeme::kCode;
          return n;
        }
        return 1;
    }
    return 1;
  }

  // The character at i_ in single quotes. Appended piece by piece: GCC 12 warns (-Wrestrict, a
  // false positive) about "'" + std::string(...) here once inlined.
  std::string quoted(std::size_t length) const {
    std::string text = "'";
    text.append(text_.substr(i_, length));
    text += '\'';
    return text;
  }

  std::optional<Problem> nonAscii(std::string& out) {
    char32_t code_point = 0;
    const std::size_t length = decodeUtf8(text_, i_, code_point);
    if (length == 0) return Problem{line_, column_, "bytes that are not UTF-8"};
    switch (state_) {
      case Lexeme::kBasic:
      case Lexeme::kMultiBasic:
        out += escaped(code_point);  // the same character once toml++ reads the escape
        break;
      case Lexeme::kComment:
        out += '?';  // comments are discarded anyway
        break;
      case Lexeme::kLiteral:
      case Lexeme::kMultiLiteral:
        // Literal strings have no escapes; their text with accents would change meaning.
        return Problem{line_, column_,
                       quoted(length) +
                           " in a single-quoted string; allowed: such characters in a "
                           "double-quoted string"};
      case Lexeme::kCode:
        return Problem{line_, column_,
                       quoted(length) +
                           " outside quotes; allowed: such characters inside a double-quoted "
                           "string (name = \"K\xC3\xB6rper\")"};
    }
    advance(length);
    return std::nullopt;
  }

  std::string_view text_;
  std::size_t i_ = 0;
  int line_ = 1, column_ = 1;
  Lexeme state_ = Lexeme::kCode;
};

}  // namespace

std::string asciiForToml(std::string_view text, const std::string& where) {
  std::string out;
  out.reserve(text.size());
  if (std::optional<Problem> problem = Rewriter(text).run(out)) {
    throw SceneError(where + ":" + std::to_string(problem->line) + ":" +
                     std::to_string(problem->column) + ": malformed TOML: " + problem->what);
  }
  return out;
}

bool tryAsciiForToml(std::string_view text, std::string& out) {
  out.clear();
  return !Rewriter(text).run(out).has_value();
}

}  // namespace collide::scene::detail
