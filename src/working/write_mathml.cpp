// SPDX-License-Identifier: MIT
// The working as MathML in a small HTML section: a heading per step, each step one <math> whose
// table aligns the equals signs, notes as <mtext>. Well-formed XML, so a page can embed it.
#include <sstream>

#include "core/markup.hpp"
#include "working/writers.hpp"

namespace collide::working {
namespace {

using text::Math;
using text::MathKind;

std::string element(const std::string& name, const std::string& content,
                    const std::string& attributes = "") {
  return "<" + name + attributes + ">" + content + "</" + name + ">";
}

std::string rowOf(const Math& math) {
  return element("mrow", mathmlMath(math));
}

std::string scriptsMathml(const Math& math) {
  const std::string base = rowOf(math.parts[0]);
  std::string sup;
  for (int k = 0; k < math.primes; ++k) sup += element("mo", "′");
  if (!math.parts[2].empty()) sup += mathmlMath(math.parts[2]);
  const bool has_sub = !math.parts[1].empty();
  if (has_sub && !sup.empty()) {
    return element("msubsup", base + rowOf(math.parts[1]) + element("mrow", sup));
  }
  if (has_sub) return element("msub", base + rowOf(math.parts[1]));
  if (!sup.empty()) return element("msup", base + element("mrow", sup));
  return base;
}

}  // namespace

std::string mathmlMath(const Math& math) {
  switch (math.kind) {
    case MathKind::kRow: {
      std::string out;
      for (const Math& part : math.parts) out += mathmlMath(part);
      return out;
    }
    case MathKind::kSymbol:
      return element("mi", core::markupEscaped(math.text),
                     math.text.size() > 2 && math.text != "n̂" && math.text != "t̂"
                         ? " mathvariant=\"italic\""
                         : "");
    case MathKind::kNumber:
      return element("mn", core::markupEscaped(math.text));
    case MathKind::kOperator:
      return element("mo", core::markupEscaped(math.text));
    case MathKind::kWord:
      return element("mi", core::markupEscaped(math.text), " mathvariant=\"normal\"");
    case MathKind::kUnit:
      return "<mspace width=\"0.17em\"/>" +
             element("mi", core::markupEscaped(math.text), " mathvariant=\"normal\"");
    case MathKind::kFraction:
      return element("mfrac", rowOf(math.parts[0]) + rowOf(math.parts[1]));
    case MathKind::kRoot:
      return element("msqrt", mathmlMath(math.parts[0]));
    case MathKind::kScripts:
      return scriptsMathml(math);
    case MathKind::kFence:
      return element("mrow", element("mo", core::markupEscaped(math.text)) +
                                 mathmlMath(math.parts[0]) +
                                 element("mo", core::markupEscaped(math.close)));
  }
  return "";
}

std::string writeMathml(const Working& working) {
  std::ostringstream out;
  out << "<section class=\"working\">\n"
      << element("h3", core::markupEscaped(working.title)) << "\n";
  for (const Step& step : working.steps) {
    out << element("h4", core::markupEscaped(step.heading)) << "\n";
    out << "<math xmlns=\"http://www.w3.org/1998/Math/MathML\" display=\"block\">"
        << "<mtable columnalign=\"right left left\">\n";
    for (const Equation& equation : step.equations) {
      std::string right;
      for (std::size_t k = 1; k < equation.sides.size(); ++k) {
        right += element("mo", "=") + mathmlMath(equation.sides[k]);
      }
      out << "<mtr>" << element("mtd", rowOf(equation.sides[0]))
          << element("mtd", element("mrow", right))
          << element("mtd", equation.note.empty()
                                ? ""
                                : element("mtext", core::markupEscaped(equation.note)))
          << "</mtr>\n";
    }
    out << "</mtable></math>\n";
  }
  out << "</section>\n";
  return out.str();
}

}  // namespace collide::working
