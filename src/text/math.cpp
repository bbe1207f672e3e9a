// SPDX-License-Identifier: MIT
#include "text/math.hpp"

#include <utility>

namespace collide::text {
namespace {

Math leaf(MathKind kind, std::string text) {
  Math math;
  math.kind = kind;
  math.text = std::move(text);
  return math;
}

// A sign first, after any bidi mark the language's minus carries (Arabic's U+061C, U+200E/F).
bool startsWithSign(std::string text) {
  for (const char* mark : {"\u061c", "\u200e", "\u200f"}) {
    while (text.rfind(mark, 0) == 0) text.erase(0, std::string(mark).size());
  }
  return text.rfind("\u2212", 0) == 0 || text.rfind("-", 0) == 0 || text.rfind("+", 0) == 0;
}

}  // namespace

Math symbol(std::string text) {
  return leaf(MathKind::kSymbol, std::move(text));
}
Math number(std::string text) {
  return leaf(MathKind::kNumber, std::move(text));
}
Math op(std::string text) {
  return leaf(MathKind::kOperator, std::move(text));
}
Math word(std::string text) {
  return leaf(MathKind::kWord, std::move(text));
}
Math unit(std::string text) {
  return leaf(MathKind::kUnit, std::move(text));
}

Math row(std::vector<Math> parts) {
  Math math;
  math.parts = std::move(parts);
  return math;
}

Math fraction(Math numerator, Math denominator) {
  Math math;
  math.kind = MathKind::kFraction;
  math.parts = {std::move(numerator), std::move(denominator)};
  return math;
}

Math root(Math radicand) {
  Math math;
  math.kind = MathKind::kRoot;
  math.parts = {std::move(radicand)};
  return math;
}

Math scripts(Math base, Math subscript, Math superscript, int primes) {
  Math math;
  math.kind = MathKind::kScripts;
  math.parts = {std::move(base), std::move(subscript), std::move(superscript)};
  math.primes = primes;
  return math;
}

Math fenced(Math body, std::string open, std::string close) {
  Math math;
  math.kind = MathKind::kFence;
  math.text = std::move(open);
  math.close = std::move(close);
  math.parts = {std::move(body)};
  return math;
}

bool isCompound(const Math& math) {
  if (math.kind == MathKind::kNumber) return startsWithSign(math.text);
  if (math.kind != MathKind::kRow) return false;
  if (math.parts.size() == 1) return isCompound(math.parts[0]);
  for (const Math& part : math.parts) {
    if (part.kind == MathKind::kOperator && part.text != "\u00b7") return true;
  }
  return false;
}

Math grouped(Math math) {
  return isCompound(math) ? fenced(std::move(math)) : math;
}

}  // namespace collide::text
