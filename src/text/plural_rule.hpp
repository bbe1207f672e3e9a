#pragma once
// The plural rule of a gettext catalogue: its Plural-Forms header ("nplurals=3; plural=(n%10==1 &&
// n%100!=11 ? 0 : ...);") parsed once into an expression and evaluated for each count. GNU
// gettext's own evaluator is private to libintl, which reads catalogues only from install paths;
// collide embeds its catalogues, so it evaluates the header itself (the C subset gettext allows:
// n, decimal numbers, ! * / % + - < > <= >= == != && || ?: and parentheses).
#include <memory>
#include <string>
#include <string_view>

namespace collide::text {

class PluralRule {
 public:
  // English: two forms, the first for exactly one.
  PluralRule();
  ~PluralRule();
  PluralRule(PluralRule&&) noexcept;
  PluralRule& operator=(PluralRule&&) noexcept;

  // Parses the value of a Plural-Forms header. Throws std::invalid_argument naming what is wrong.
  static PluralRule parse(std::string_view header_value);

  int forms() const { return forms_; }
  // The index of the plural form for count n, in [0, forms()); an expression that yields an
  // index out of range gives 0 (as libintl does).
  int formFor(unsigned long n) const;

  struct Node;

 private:
  int forms_ = 2;
  std::unique_ptr<Node> expression_;
};

}  // namespace collide::text
