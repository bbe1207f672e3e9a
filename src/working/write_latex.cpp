// SPDX-License-Identifier: MIT
// The working as LaTeX (each step an amsmath align*, equals signs aligned, notes in \text) and as
// Markdown (each equation in $…$, the same LaTeX inside).
#include <array>
#include <sstream>
#include <string_view>
#include <utility>

#include "working/writers.hpp"

namespace collide::working {
namespace {

using text::Math;
using text::MathKind;

// Unicode characters of the working's math and their LaTeX (math mode).
constexpr std::array<std::pair<std::string_view, std::string_view>, 20> kMathCharacters = {{
    {"−", "-"},         {"·", "\\cdot "},   {"×", "\\times "}, {"∫", "\\int "},   {"Δ", "\\Delta "},
    {"≈", "\\approx "}, {"μ", "\\mu "},     {"µ", "\\mu "},    {"θ", "\\theta "}, {"π", "\\pi "},
    {"ω", "\\omega "},  {"n̂", "\\hat{n}"},  {"t̂", "\\hat{t}"}, {"⌈", "\\lceil "}, {"⌉", "\\rceil "},
    {"²", "^{2}"},      {"°", "^{\\circ}"}, {"\u00a0", "\\,"}, {"\u202f", "\\,"}, {"%", "\\%"},
}};

// `text` with the characters above replaced; `ascii_run` wraps runs of two or more letters (a
// symbol "KE") so they read as one symbol.
std::string mathCharacters(std::string_view text) {
  std::string out;
  std::size_t k = 0;
  while (k < text.size()) {
    bool replaced = false;
    for (const auto& [from, to] : kMathCharacters) {
      if (text.substr(k, from.size()) == from) {
        out += to;
        k += from.size();
        replaced = true;
        break;
      }
    }
    if (replaced) continue;
    const char c = text[k];
    if (c == '{' || c == '}' || c == '#' || c == '&' || c == '_' || c == '$') out += '\\';
    out += c;
    ++k;
  }
  return out;
}

bool isAsciiLetters(std::string_view text) {
  for (char c : text) {
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'))) return false;
  }
  return true;
}

bool isAscii(std::string_view text) {
  for (char c : text) {
    if (static_cast<unsigned char>(c) >= 0x80) return false;
  }
  return true;
}

std::string symbolLatex(const std::string& symbol) {
  if (symbol.size() > 1 && isAsciiLetters(symbol)) return "\\mathit{" + symbol + "}";
  const std::string mapped = mathCharacters(symbol);
  // A symbol in another script (a translated one): as text, which pdflatex may not have.
  return isAscii(mapped) ? mapped : "\\text{" + latexText(symbol) + "}";
}

std::string numberLatex(const std::string& number) {
  std::string out;
  for (char c : mathCharacters(number)) {
    if (c == ',') {
      out += "{,}";  // a group separator, or a decimal comma: no space after it
    } else {
      out += c;
    }
  }
  return out;
}

std::string wordLatex(const std::string& word) {
  if (word == "arctan") return "\\arctan ";
  return "\\mathrm{" + mathCharacters(word) + "}";
}

std::string scriptsLatex(const Math& math) {
  // Appended piece by piece: GCC 12 warns (-Wrestrict) on "literal" + a temporary string.
  std::string out = "{";
  out += latexMath(math.parts[0]);
  out += "}";
  if (!math.parts[1].empty()) {
    out += "_{";
    out += latexMath(math.parts[1]);
    out += "}";
  }
  std::string sup;
  for (int k = 0; k < math.primes; ++k) sup += "\\prime ";
  if (!math.parts[2].empty()) sup += latexMath(math.parts[2]);
  if (!sup.empty()) {
    out += "^{";
    out += sup;
    out += "}";
  }
  return out;
}

std::string fenceLatex(const Math& math) {
  return "\\left" + mathCharacters(math.text) + latexMath(math.parts[0]) + "\\right" +
         mathCharacters(math.close);
}

}  // namespace

std::string latexMath(const Math& math) {
  switch (math.kind) {
    case MathKind::kRow: {
      std::string out;
      for (const Math& part : math.parts) out += latexMath(part);
      return out;
    }
    case MathKind::kSymbol:
      return symbolLatex(math.text);
    case MathKind::kNumber:
      return numberLatex(math.text);
    case MathKind::kOperator:
      return mathCharacters(math.text) + (math.text == "," ? "\\," : "");
    case MathKind::kWord:
      return wordLatex(math.text);
    case MathKind::kUnit:
      return (math.text.rfind("°", 0) == 0 ? "" : "\\,") +
             ("\\mathrm{" + mathCharacters(math.text) + "}");
    case MathKind::kFraction:
      if (math.parts[0].kind == MathKind::kNumber && math.parts[0].text == "1" &&
          math.parts[1].kind == MathKind::kNumber && math.parts[1].text == "2") {
        return "\\tfrac{1}{2}";  // ½ as a factor, at the size of the symbols beside it
      }
      return "\\frac{" + latexMath(math.parts[0]) + "}{" + latexMath(math.parts[1]) + "}";
    case MathKind::kRoot:
      return "\\sqrt{" + latexMath(math.parts[0]) + "}";
    case MathKind::kScripts:
      return scriptsLatex(math);
    case MathKind::kFence:
      return fenceLatex(math);
  }
  return "";
}

std::string latexText(const std::string& words) {
  static const std::array<std::pair<std::string_view, std::string_view>, 22> kText = {{
      {"\\", "\\textbackslash{}"},
      {"{", "\\{"},
      {"}", "\\}"},
      {"#", "\\#"},
      {"$", "\\$"},
      {"%", "\\%"},
      {"&", "\\&"},
      {"_", "\\_"},
      {"~", "\\textasciitilde{}"},
      {"^", "\\^{}"},
      {"½", "$\\frac12$"},
      {"²", "$^2$"},
      {"θ", "$\\theta$"},
      {"π", "$\\pi$"},
      {"−", "$-$"},
      {"′", "$'$"},
      // The notes of a release's working ("Σp = 0", "s = v₂ − v₁", "½μs′²", "e > 1"): OT1 has
      // no "<" or ">" in text (they print as "¡" and "¿").
      {"Σ", "$\\Sigma$"},
      {"μ", "$\\mu$"},
      {"₁", "$_1$"},
      {"₂", "$_2$"},
      {"<", "$<$"},
      {">", "$>$"},
  }};
  std::string out;
  std::size_t k = 0;
  while (k < words.size()) {
    bool replaced = false;
    for (const auto& [from, to] : kText) {
      if (std::string_view(words).substr(k, from.size()) == from) {
        out += to;
        k += from.size();
        replaced = true;
        break;
      }
    }
    if (!replaced) out += words[k++];
  }
  return out;
}

std::string writeLatex(const Working& working) {
  std::ostringstream out;
  out << "% "
      << "collide solve: needs \\usepackage{amsmath}\n";
  out << "\\noindent\\textbf{" << latexText(working.title) << "}\n";
  for (const Step& step : working.steps) {
    out << "\n\\noindent\\emph{" << latexText(step.heading) << "}\n\\begin{align*}\n";
    for (std::size_t e = 0; e < step.equations.size(); ++e) {
      const Equation& equation = step.equations[e];
      out << "  " << latexMath(equation.sides[0]);
      for (std::size_t k = 1; k < equation.sides.size(); ++k) {
        out << (k == 1 ? " &= " : " = ") << latexMath(equation.sides[k]);
      }
      if (!equation.note.empty()) out << " && \\text{" << latexText(equation.note) << "}";
      out << (e + 1 < step.equations.size() ? " \\\\\n" : "\n");
    }
    out << "\\end{align*}\n";
  }
  return out.str();
}

std::string writeMarkdown(const Working& working) {
  std::ostringstream out;
  out << "**" << working.title << "**\n";
  for (const Step& step : working.steps) {
    out << "\n*" << step.heading << "*\n\n";
    for (const Equation& equation : step.equations) {
      out << "- $" << latexMath(equation.sides[0]);
      for (std::size_t k = 1; k < equation.sides.size(); ++k) {
        out << " = " << latexMath(equation.sides[k]);
      }
      out << "$";
      if (!equation.note.empty()) out << " (" << equation.note << ")";
      out << "\n";
    }
  }
  return out.str();
}

}  // namespace collide::working
