// SPDX-License-Identifier: MIT
#pragma once
// A working written out: Unicode text for a terminal, LaTeX (amsmath align*), Markdown with $…$
// math, or MathML for a web page. The words and symbols are those of the working (the active
// language); the LaTeX is meant for pdflatex, so its words must be in a Latin script there.
#include <string>
#include <vector>

#include "text/math.hpp"
#include "working/working.hpp"

namespace collide::working {

enum class Format { kText, kLatex, kMarkdown, kMathml };

std::string writeWorking(const Working& working, Format format);

// One formula as each writer writes it (for captions and tests).
std::string textMath(const text::Math& math);
std::string latexMath(const text::Math& math);
std::string mathmlMath(const text::Math& math);

// Words for LaTeX's text mode: its special characters escaped, the few math characters the
// working's words use (½, ², θ, π, −) written as LaTeX.
std::string latexText(const std::string& words);

// The working as words a screen reader can say, in the active language (write_speech.cpp):
// "v 1 prime equals minus 0.250 metres per second". speakSteps reads the steps of the kinds
// given, each as "heading: equation; equation.".
std::string speakMath(const text::Math& math);
std::string speakEquation(const Equation& equation);
std::string speakSteps(const Working& working, const std::vector<StepKind>& kinds);

std::string writeText(const Working& working);
std::string writeLatex(const Working& working);
std::string writeMarkdown(const Working& working);
std::string writeMathml(const Working& working);

}  // namespace collide::working
