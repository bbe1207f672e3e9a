// SPDX-License-Identifier: MIT
// The working as words a screen reader can say, for captions and alt text: "v₁′ = −0.250 m/s"
// becomes "v 1 prime equals minus 0.250 metres per second". Made from the math trees, as the other
// writers are, so a fraction is read as "over", a root as "the square root of", a square as
// "squared", whatever the text form would print; the words come from the catalogues.
#include <algorithm>
#include <array>
#include <string_view>
#include <utility>

#include "text/translate.hpp"
#include "working/writers.hpp"

namespace collide::working {
namespace {

using text::Math;
using text::MathKind;
using text::NC_;

// A unit's words from the table below (marked there with NC_ for the catalogues).
std::string say(const char* words) {
  return text::trc("spoken math", words);
}

// The units the workings write, as words. A unit not listed is left as written.
constexpr std::array<std::pair<std::string_view, const char*>, 16> kUnitWords = {{
    {"m/s", NC_("spoken math", "metres per second")},
    {"m/s²", NC_("spoken math", "metres per second squared")},
    {"kg", NC_("spoken math", "kilograms")},
    {"J", NC_("spoken math", "joules")},
    {"mJ", NC_("spoken math", "millijoules")},
    {"kJ", NC_("spoken math", "kilojoules")},
    {"s", NC_("spoken math", "seconds")},
    {"m", NC_("spoken math", "metres")},
    {"N", NC_("spoken math", "newtons")},
    {"N·s", NC_("spoken math", "newton seconds")},
    {"mN·s", NC_("spoken math", "millinewton seconds")},
    {"rad", NC_("spoken math", "radians")},
    {"rad/s", NC_("spoken math", "radians per second")},
    {"kg·m²", NC_("spoken math", "kilogram square metres")},
    {"kg·m²/s", NC_("spoken math", "kilogram square metres per second")},
    {"°", NC_("spoken math", "degrees")},
}};

std::string unitWords(const std::string& unit) {
  for (const auto& [symbol, words] : kUnitWords) {
    if (unit == symbol) return say(words);
  }
  return unit;
}

std::string operatorWords(const std::string& op) {
  // TRANSLATORS: the working of a collision read aloud in alt text and captions, word by word:
  // "v 1 prime equals minus 0.250 metres per second". Write the words as a screen reader in
  // your language should say them.
  if (op == "=") return text::trc("spoken math", "equals");
  if (op == "+") return text::trc("spoken math", "plus");
  if (op == "−") return text::trc("spoken math", "minus");
  if (op == "·" || op == "×") return text::trc("spoken math", "times");
  if (op == "≈") return text::trc("spoken math", "is about");
  if (op == "∫") return text::trc("spoken math", "the integral of");
  return op;  // "," between a vector's parts, "Δ" (read by its name)
}

// "−0.250" as "minus 0.250": a screen reader may read "−" as a dash. The sign may follow a
// bidi mark (Arabic writes U+061C before it), which a sign read as a word no longer needs.
std::string numberWords(const std::string& number) {
  std::size_t start = 0;
  for (const std::string_view mark : {"\u061c", "\u200e", "\u200f"}) {
    if (number.compare(start, mark.size(), mark) == 0) start += mark.size();
  }
  const std::string_view minus = "\u2212";
  if (number.compare(start, minus.size(), minus) == 0) {
    return text::trc("spoken math", "minus") + " " + number.substr(start + minus.size());
  }
  if (number.compare(start, 1, "+") == 0) {
    return text::trc("spoken math", "plus") + " " + number.substr(start + 1);
  }
  return number;
}

// Words joined by single spaces, none at either end.
void appendWords(std::string& out, const std::string& words) {
  if (words.empty()) return;
  if (!out.empty() && out.back() != ' ' && words != ",") out += ' ';
  out += words;
}

bool isSpokenNumber(const Math& math, const char* text) {
  return math.kind == MathKind::kNumber && math.text == text;
}

// A part that needs brackets spoken around it when it is divided, rooted or raised: a row with
// an operator at its top level ("m 1 plus m 2"); a product ("m 1 m 2") reads without.
std::string spokenGroup(const Math& math) {
  const bool compound = math.kind == MathKind::kRow &&
                        std::any_of(math.parts.begin(), math.parts.end(), [](const Math& part) {
                          return part.kind == MathKind::kOperator;
                        });
  if (!compound) return speakMath(math);
  return text::trc("spoken math", "open bracket") + " " + speakMath(math) + " " +
         text::trc("spoken math", "close bracket");
}

// A row of one part is that part: the 2 of a square is written row({number("2")}).
const Math& alone(const Math& math) {
  return math.kind == MathKind::kRow && math.parts.size() == 1 ? alone(math.parts[0]) : math;
}

std::string powerWords(const Math& exponent) {
  const Math& power = alone(exponent);
  if (isSpokenNumber(power, "2")) return text::trc("spoken math", "squared");
  if (isSpokenNumber(power, "3")) return text::trc("spoken math", "cubed");
  return text::trc("spoken math", "to the power") + " " + spokenGroup(power);
}

std::string scriptsWords(const Math& math) {
  std::string out = speakMath(math.parts[0]);
  appendWords(out, speakMath(math.parts[1]));  // the subscript: "v 1"
  for (int k = 0; k < math.primes; ++k) appendWords(out, text::trc("spoken math", "prime"));
  if (!math.parts[2].empty()) appendWords(out, powerWords(math.parts[2]));
  return out;
}

// "(1 + e)" as "open bracket 1 plus e close bracket"; "⌈π/θ⌉" adds "rounded up".
std::string fenceWords(const Math& math) {
  std::string out = text::trc("spoken math", "open bracket");
  appendWords(out, speakMath(math.parts[0]));
  appendWords(out, text::trc("spoken math", "close bracket"));
  if (math.text == "⌈") appendWords(out, text::trc("spoken math", "rounded up"));
  return out;
}

}  // namespace

std::string speakMath(const Math& math) {
  switch (math.kind) {
    case MathKind::kRow: {
      std::string out;
      for (const Math& part : math.parts) appendWords(out, speakMath(part));
      return out;
    }
    case MathKind::kNumber:
      return numberWords(math.text);
    case MathKind::kOperator:
      return operatorWords(math.text);
    case MathKind::kUnit:
      return unitWords(math.text);
    case MathKind::kFraction:
      if (isSpokenNumber(alone(math.parts[0]), "1") && isSpokenNumber(alone(math.parts[1]), "2"))
        return text::trc("spoken math", "one half");
      return spokenGroup(math.parts[0]) + " " + text::trc("spoken math", "over") + " " +
             spokenGroup(math.parts[1]);
    case MathKind::kRoot:
      return text::trc("spoken math", "the square root of") + " " + spokenGroup(math.parts[0]);
    case MathKind::kScripts:
      return scriptsWords(math);
    case MathKind::kFence:
      return fenceWords(math);
    default:  // a symbol or a word, read as written
      return math.text;
  }
}

std::string speakEquation(const Equation& equation) {
  std::string out;
  for (std::size_t k = 0; k < equation.sides.size(); ++k) {
    if (k > 0) appendWords(out, text::trc("spoken math", "equals"));
    appendWords(out, speakMath(equation.sides[k]));
  }
  return out;
}

std::string speakSteps(const Working& working, const std::vector<StepKind>& kinds) {
  std::string out;
  for (const Step& step : working.steps) {
    if (std::find(kinds.begin(), kinds.end(), step.kind) == kinds.end()) continue;
    std::string sentence = step.heading + ": ";
    for (std::size_t k = 0; k < step.equations.size(); ++k) {
      if (k > 0) sentence += text::trc("punctuation", "; ");
      sentence += speakEquation(step.equations[k]);
    }
    appendWords(out, sentence + ".");
  }
  return out;
}

}  // namespace collide::working
