// SPDX-License-Identifier: MIT
#pragma once
// Mathematics as a small tree: symbols, numbers, operators, words, fractions, roots, sub- and
// superscripts with primes, and fences. Plain data with no layout: the working of a collision
// (src/working) is built as such trees and written as Unicode text, LaTeX, Markdown or MathML, or
// typeset by a painter. Numbers arrive already formatted (text/number_format.hpp), so every
// writer shows the same figures as the picture's readouts.
#include <string>
#include <vector>

namespace collide::text {

enum class MathKind {
  kRow,       // parts side by side
  kSymbol,    // an italic variable: "m", "v", "μ", "KE" (a translated symbol may be a word)
  kNumber,    // a formatted number: "−0.250", "1.00"
  kOperator,  // "=", "+", "−", "·", "×"
  kWord,      // upright words: a note, a function name ("arctan"), an index letter
  kUnit,      // a unit after a number: "m/s", "kg", "J"
  kFraction,  // parts: numerator, denominator
  kRoot,      // parts: radicand (a square root)
  kScripts,   // parts: base, subscript, superscript (an empty row where there is none)
  kFence,     // parts: body, between `text` (open) and `close`: "(", ")"; "⌈", "⌉"
};

struct Math {
  MathKind kind = MathKind::kRow;
  std::string text;         // symbol, number, operator, word or unit; a fence's opening
  std::string close;        // a fence's closing
  std::vector<Math> parts;  // see MathKind
  int primes = 0;           // kScripts: primes after the base (v₁′)

  bool empty() const { return kind == MathKind::kRow && parts.empty(); }
};

Math symbol(std::string text);
Math number(std::string text);
Math op(std::string text);
Math word(std::string text);
Math unit(std::string text);
Math row(std::vector<Math> parts);
Math fraction(Math numerator, Math denominator);
Math root(Math radicand);
// base with a subscript, a superscript and primes; empty rows where there is none.
Math scripts(Math base, Math subscript, Math superscript = {}, int primes = 0);
Math fenced(Math body, std::string open = "(", std::string close = ")");

// Whether a part needs brackets when it is multiplied or raised to a power: a row with an
// operator at its top level ("1 + e"), or a number with a sign ("−1.00").
bool isCompound(const Math& math);
// The part in parentheses when isCompound, else as it is.
Math grouped(Math math);

}  // namespace collide::text
