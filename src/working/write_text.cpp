// SPDX-License-Identifier: MIT
// The working as Unicode text for a terminal: fractions on one line (a/b, brackets where the
// parts need them), √, subscript and superscript digits, primes, each step's equals signs
// aligned.
#include <algorithm>
#include <sstream>

#include "working/writers.hpp"

namespace collide::working {
namespace {

using text::Math;
using text::MathKind;

// Unicode's subscript and superscript forms of the characters that have them.
std::string scripted(const std::string& plain, bool sub, bool& complete) {
  static const char* const kSubDigits[] = {"₀", "₁", "₂", "₃", "₄", "₅", "₆", "₇", "₈", "₉"};
  static const char* const kSupDigits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  static const std::string kSubLetters = "aehijklmnoprstuvx";
  static const char* const kSubLetterForms[] = {"ₐ", "ₑ", "ₕ", "ᵢ", "ⱼ", "ₖ", "ₗ", "ₘ", "ₙ",
                                                "ₒ", "ₚ", "ᵣ", "ₛ", "ₜ", "ᵤ", "ᵥ", "ₓ"};
  std::string out;
  for (char c : plain) {
    if (c >= '0' && c <= '9') {
      out += sub ? kSubDigits[c - '0'] : kSupDigits[c - '0'];
    } else if (sub && kSubLetters.find(c) != std::string::npos) {
      out += kSubLetterForms[kSubLetters.find(c)];
    } else {
      complete = false;
      return plain;
    }
  }
  return out;
}

// Whether a part of a one-line fraction or a root needs brackets: it holds an operator (a
// product "1.00 · 2.00" too), a fraction, or a signed number.
bool needsBrackets(const Math& math) {
  if (math.kind == MathKind::kFraction) return true;
  if (math.kind == MathKind::kNumber) return text::isCompound(math);
  if (math.kind != MathKind::kRow) return false;
  if (math.parts.size() == 1) return needsBrackets(math.parts[0]);
  for (const Math& part : math.parts) {
    if (part.kind == MathKind::kOperator || part.kind == MathKind::kFraction) return true;
  }
  return false;
}

std::string bracketed(const Math& math, bool products_too = false) {
  const std::string inner = textMath(math);
  const bool product = math.kind == MathKind::kRow && math.parts.size() > 1;
  return needsBrackets(math) || (products_too && product) ? "(" + inner + ")" : inner;
}

bool isNumber(const Math& math, const char* text) {
  return math.kind == MathKind::kNumber && math.text == text;
}

// The plain characters of a script (its leaves), for the Unicode forms.
std::string leaves(const Math& math) {
  if (math.kind == MathKind::kRow) {
    std::string out;
    for (const Math& part : math.parts) out += leaves(part);
    return out;
  }
  return math.kind == MathKind::kNumber || math.kind == MathKind::kWord ||
                 math.kind == MathKind::kSymbol
             ? math.text
             : "\x01";  // anything else: no Unicode form
}

std::string scriptText(const Math& script, bool sub) {
  if (script.empty()) return "";
  bool complete = true;
  const std::string forms = scripted(leaves(script), sub, complete);
  if (complete) return forms;
  return std::string(sub ? "_" : "^") + bracketed(script);
}

std::string primesText(int primes) {
  std::string out;
  for (int k = 0; k < primes; ++k) out += "′";
  return out;
}

bool spacedOperator(const std::string& op) {
  return op == "+" || op == "−" || op == "·" || op == "×" || op == "=" || op == "≈";
}

std::string rowText(const Math& math) {
  std::string out;
  for (std::size_t k = 0; k < math.parts.size(); ++k) {
    const Math& part = math.parts[k];
    if (part.kind == MathKind::kOperator) {
      if (k > 0 && spacedOperator(part.text)) {
        out += " " + part.text + " ";
      } else {
        out += part.text + (part.text == "," || part.text == ";" || part.text == "؛" ? " " : "");
      }
    } else if (part.kind == MathKind::kUnit) {
      out += (part.text.rfind("°", 0) == 0 ? "" : " ") + part.text;
    } else if (part.kind == MathKind::kWord && part.text.size() > 1 && k + 1 < math.parts.size()) {
      out += part.text + " ";  // a function name before its argument: "arctan √x"
    } else {
      out += textMath(part);
    }
  }
  return out;
}

}  // namespace

std::string textMath(const Math& math) {
  switch (math.kind) {
    case MathKind::kRow:
      return rowText(math);
    case MathKind::kFraction:
      if (isNumber(math.parts[0], "1") && isNumber(math.parts[1], "2")) return "½";
      return bracketed(math.parts[0]) + "/" + bracketed(math.parts[1], true);
    case MathKind::kRoot:
      return "√" + bracketed(math.parts[0], true);
    case MathKind::kScripts:
      return textMath(math.parts[0]) + scriptText(math.parts[1], true) + primesText(math.primes) +
             scriptText(math.parts[2], false);
    case MathKind::kFence:
      return math.text + textMath(math.parts[0]) + math.close;
    default:
      return math.text;
  }
}

namespace {

// Characters, not bytes: what lines up in a terminal (the working's symbols are narrow).
std::size_t width(const std::string& text) {
  return std::size_t(std::count_if(text.begin(), text.end(), [](char c) {
    return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  }));
}

void writeStep(const Step& step, std::ostream& out) {
  out << step.heading << "\n";
  std::size_t left_width = 0;
  for (const Equation& equation : step.equations) {
    left_width = std::max(left_width, width(textMath(equation.sides[0])));
  }
  for (const Equation& equation : step.equations) {
    const std::string left = textMath(equation.sides[0]);
    out << "  " << std::string(left_width - width(left), ' ') << left;
    for (std::size_t k = 1; k < equation.sides.size(); ++k)
      out << " = " << textMath(equation.sides[k]);
    if (!equation.note.empty()) out << "    (" << equation.note << ")";
    out << "\n";
  }
}

}  // namespace

std::string writeText(const Working& working) {
  std::ostringstream out;
  out << working.title << "\n";
  for (const Step& step : working.steps) {
    out << "\n";
    writeStep(step, out);
  }
  return out.str();
}

std::string writeWorking(const Working& working, Format format) {
  switch (format) {
    case Format::kText:
      return writeText(working);
    case Format::kLatex:
      return writeLatex(working);
    case Format::kMarkdown:
      return writeMarkdown(working);
    case Format::kMathml:
      return writeMathml(working);
  }
  return "";
}

}  // namespace collide::working
