#include "text/plural_rule.hpp"

#include <cctype>
#include <stdexcept>

namespace collide::text {

// One node of the expression tree: a number, n, or an operator with up to three operands.
struct PluralRule::Node {
  enum class Kind { kNumber, kN, kNot, kBinary, kChoice } kind = Kind::kNumber;
  unsigned long value = 0;
  std::string op;  // kBinary: "*", "/", "%", "+", "-", "<", ">", "<=", ">=", "==", "!=", "&&", "||"
  std::unique_ptr<Node> a, b, c;

  unsigned long evaluate(unsigned long n) const {
    switch (kind) {
      case Kind::kNumber:
        return value;
      case Kind::kN:
        return n;
      case Kind::kNot:
        return a->evaluate(n) == 0 ? 1 : 0;
      case Kind::kChoice:
        return a->evaluate(n) != 0 ? b->evaluate(n) : c->evaluate(n);
      case Kind::kBinary:
        break;
    }
    const unsigned long x = a->evaluate(n);
    if (op == "&&") return x != 0 && b->evaluate(n) != 0;
    if (op == "||") return x != 0 || b->evaluate(n) != 0;
    const unsigned long y = b->evaluate(n);
    if (op == "*") return x * y;
    if (op == "/") return y == 0 ? 0 : x / y;  // a header dividing by zero must not crash us
    if (op == "%") return y == 0 ? 0 : x % y;
    if (op == "+") return x + y;
    if (op == "-") return x - y;
    if (op == "<") return x < y;
    if (op == ">") return x > y;
    if (op == "<=") return x <= y;
    if (op == ">=") return x >= y;
    if (op == "==") return x == y;
    return x != y;  // "!="
  }
};

namespace {

using Node = PluralRule::Node;
using NodePtr = std::unique_ptr<Node>;

// Recursive descent over the C operator precedence levels gettext's grammar uses.
class Parser {
 public:
  explicit Parser(std::string_view text) : text_(text) {}

  NodePtr parseWhole() {
    NodePtr node = choice();
    skipSpace();
    if (pos_ != text_.size()) fail("unexpected '" + std::string(1, text_[pos_]) + "'");
    return node;
  }

 private:
  static constexpr int kMaxDepth = 64;  // nesting beyond this is not a plural rule

  [[noreturn]] void fail(const std::string& what) const {
    throw std::invalid_argument("plural expression '" + std::string(text_) + "': " + what +
                                " at character " + std::to_string(pos_ + 1));
  }
  void skipSpace() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  bool accept(std::string_view token) {
    skipSpace();
    if (text_.substr(pos_, token.size()) != token) return false;
    // "<" must not take the first half of "<=", "!" not of "!=".
    if (token.size() == 1 && pos_ + 1 < text_.size() && text_[pos_ + 1] == '=' &&
        (token == "<" || token == ">" || token == "!")) {
      return false;
    }
    pos_ += token.size();
    return true;
  }
  static NodePtr binary(std::string op, NodePtr a, NodePtr b) {
    auto node = std::make_unique<Node>();
    node->kind = Node::Kind::kBinary;
    node->op = std::move(op);
    node->a = std::move(a);
    node->b = std::move(b);
    return node;
  }

  NodePtr choice() {
    if (++depth_ > kMaxDepth) fail("nested too deeply");
    NodePtr condition = logicalOr();
    if (accept("?")) {
      auto node = std::make_unique<Node>();
      node->kind = Node::Kind::kChoice;
      node->a = std::move(condition);
      node->b = choice();
      if (!accept(":")) fail("':' expected");
      node->c = choice();
      condition = std::move(node);
    }
    --depth_;
    return condition;
  }
  NodePtr logicalOr() {
    NodePtr left = logicalAnd();
    while (accept("||")) left = binary("||", std::move(left), logicalAnd());
    return left;
  }
  NodePtr logicalAnd() {
    NodePtr left = equality();
    while (accept("&&")) left = binary("&&", std::move(left), equality());
    return left;
  }
  NodePtr equality() {
    NodePtr left = relation();
    for (;;) {
      if (accept("==")) {
        left = binary("==", std::move(left), relation());
      } else if (accept("!=")) {
        left = binary("!=", std::move(left), relation());
      } else {
        return left;
      }
    }
  }
  NodePtr relation() {
    NodePtr left = sum();
    for (const char* op : {"<=", ">=", "<", ">"}) {
      if (accept(op)) return binary(op, std::move(left), sum());
    }
    return left;
  }
  NodePtr sum() {
    NodePtr left = product();
    for (;;) {
      if (accept("+")) {
        left = binary("+", std::move(left), product());
      } else if (accept("-")) {
        left = binary("-", std::move(left), product());
      } else {
        return left;
      }
    }
  }
  NodePtr product() {
    NodePtr left = unary();
    for (;;) {
      if (accept("*")) {
        left = binary("*", std::move(left), unary());
      } else if (accept("/")) {
        left = binary("/", std::move(left), unary());
      } else if (accept("%")) {
        left = binary("%", std::move(left), unary());
      } else {
        return left;
      }
    }
  }
  NodePtr unary() {
    if (accept("!")) {
      if (++depth_ > kMaxDepth) fail("nested too deeply");
      auto node = std::make_unique<Node>();
      node->kind = Node::Kind::kNot;
      node->a = unary();
      --depth_;
      return node;
    }
    return primary();
  }
  NodePtr primary() {
    skipSpace();
    auto node = std::make_unique<Node>();
    if (accept("(")) {
      node = choice();
      if (!accept(")")) fail("')' expected");
      return node;
    }
    if (pos_ < text_.size() && text_[pos_] == 'n') {
      ++pos_;
      node->kind = Node::Kind::kN;
      return node;
    }
    if (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) {
      unsigned long value = 0;
      while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) {
        if (value > 100'000'000) fail("number too large");
        value = value * 10 + static_cast<unsigned long>(text_[pos_++] - '0');
      }
      node->value = value;
      return node;
    }
    fail(pos_ < text_.size() ? "unexpected '" + std::string(1, text_[pos_]) + "'"
                             : "unexpected end");
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  int depth_ = 0;
};

// The value of `name=` up to the next ';' in a header such as "nplurals=2; plural=(n != 1);".
std::string_view field(std::string_view header, std::string_view name) {
  std::size_t at = 0;
  while ((at = header.find(name, at)) != std::string_view::npos) {
    const bool starts =
        at == 0 || header[at - 1] == ' ' || header[at - 1] == ';' || header[at - 1] == '\t';
    std::size_t after = at + name.size();
    while (after < header.size() && header[after] == ' ') ++after;
    if (starts && after < header.size() && header[after] == '=') {
      const std::size_t end = header.find(';', after);
      return header.substr(
          after + 1, end == std::string_view::npos ? std::string_view::npos : end - after - 1);
    }
    at += name.size();
  }
  throw std::invalid_argument("Plural-Forms '" + std::string(header) + "' has no " +
                              std::string(name) + "=");
}

}  // namespace

PluralRule::PluralRule() : expression_(Parser("n != 1").parseWhole()) {}
PluralRule::~PluralRule() = default;
PluralRule::PluralRule(PluralRule&&) noexcept = default;
PluralRule& PluralRule::operator=(PluralRule&&) noexcept = default;

PluralRule PluralRule::parse(std::string_view header_value) {
  PluralRule rule;
  const std::string_view count = field(header_value, "nplurals");
  int forms = 0;
  for (char c : count) {
    if (c == ' ') continue;
    if (!std::isdigit(static_cast<unsigned char>(c)) || forms > 100) {
      throw std::invalid_argument("Plural-Forms: nplurals='" + std::string(count) +
                                  "' is not a count of forms (1 to 100)");
    }
    forms = forms * 10 + (c - '0');
  }
  if (forms < 1 || forms > 100) {
    throw std::invalid_argument("Plural-Forms: nplurals='" + std::string(count) +
                                "' is not a count of forms (1 to 100)");
  }
  rule.forms_ = forms;
  rule.expression_ = Parser(field(header_value, "plural")).parseWhole();
  return rule;
}

int PluralRule::formFor(unsigned long n) const {
  const unsigned long index = expression_->evaluate(n);
  return index < static_cast<unsigned long>(forms_) ? static_cast<int>(index) : 0;
}

}  // namespace collide::text
