#include "report/figure_bundle.hpp"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <utility>
#include <vector>

namespace collide::report {
namespace {

// Characters of collide's labels that LaTeX's text mode lacks, as LaTeX; anything else non-ASCII
// is kept (pdfLaTeX with utf8 input, XeLaTeX and LuaLaTeX read it).
const std::vector<std::pair<std::string, std::string>>& latexReplacements() {
  static const std::vector<std::pair<std::string, std::string>> table = {
      {"\\", "\\textbackslash{}"},
      {"{", "\\{"},
      {"}", "\\}"},
      {"$", "\\$"},
      {"&", "\\&"},
      {"%", "\\%"},
      {"#", "\\#"},
      {"_", "\\_"},
      {"~", "\\textasciitilde{}"},
      {"^", "\\textasciicircum{}"},
      {"\u2212", "$-$"},
      {"\u00b7", "$\\cdot$"},
      {"\u00d7", "$\\times$"},
      {"\u2032", "$'$"},
      {"\u00b1", "$\\pm$"},
      {"\u2248", "$\\approx$"},
      {"\u03a3", "$\\Sigma$"},
      {"\u0394", "$\\Delta$"},
      {"\u03b8", "$\\theta$"},
      {"\u03bc", "$\\mu$"},
      {"\u03c9", "$\\omega$"},
      {"\u03c0", "$\\pi$"},
      {"\u2026", "\\dots{}"},
      {"\u00b2", "\\textsuperscript{2}"},
      {"\u00b3", "\\textsuperscript{3}"}};
  return table;
}

std::string latexText(const std::string& text) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    bool replaced = false;
    for (const auto& [from, to] : latexReplacements()) {
      if (text.compare(i, from.size(), from) == 0) {
        out += to;
        i += from.size();
        replaced = true;
        break;
      }
    }
    if (replaced) continue;
    // Subscript digits U+2080..U+2089: E2 82 80..89.
    if (i + 2 < text.size() && static_cast<unsigned char>(text[i]) == 0xE2 &&
        static_cast<unsigned char>(text[i + 1]) == 0x82 &&
        static_cast<unsigned char>(text[i + 2]) >= 0x80 &&
        static_cast<unsigned char>(text[i + 2]) <= 0x89) {
      out += "\\textsubscript{";
      out += static_cast<char>('0' + (static_cast<unsigned char>(text[i + 2]) - 0x80));
      out += "}";
      i += 3;
      continue;
    }
    out += text[i] == '\n' ? ' ' : text[i];
    ++i;
  }
  return out;
}

// A comment line per line of text: nothing in it can end the comment.
std::string latexComment(const std::string& text) {
  std::string out = "% ";
  for (char c : text) out += c == '\n' ? std::string("\n% ") : std::string(1, c);
  return out + "\n";
}

// Letters, digits and '-' of the file's stem: a \label that any LaTeX accepts.
std::string labelOf(const std::string& path) {
  std::string out;
  for (char c : std::filesystem::path(path).stem().string()) {
    out += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  }
  return "fig:" + out;
}

std::string markdownEscaped(const std::string& text, const std::string& special) {
  std::string out;
  for (char c : text) {
    if (c == '\n') {
      out += ' ';
      continue;
    }
    if (special.find(c) != std::string::npos) out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

std::string latexFigure(const FigureBundle& bundle) {
  const std::string file = std::filesystem::path(bundle.image_path).filename().string();
  std::string width = "\\linewidth";
  if (bundle.width_cm) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4gcm", *bundle.width_cm);
    width = text;
  }
  std::string out;
  out += "% Figure made by collide; needs \\usepackage{graphicx}.\n";
  out += latexComment("Alt text: " + bundle.alt_text);
  out += "\\begin{figure}[htbp]\n";
  out += "  \\centering\n";
  out += "  \\includegraphics[width=" + width + "]{" + file + "}\n";
  out += "  \\caption{" + latexText(bundle.caption) + "}\n";
  out += "  \\label{" + labelOf(bundle.image_path) + "}\n";
  out += "\\end{figure}\n";
  return out;
}

std::string markdownFigure(const FigureBundle& bundle) {
  const std::string file = std::filesystem::path(bundle.image_path).filename().string();
  // Spaces and parentheses in the file name would end the link: angle brackets keep it whole.
  const bool plain = file.find_first_of(" ()<>") == std::string::npos;
  return "![" + markdownEscaped(bundle.alt_text, "[]\\") + "](" +
         (plain ? file : "<" + file + ">") + " \"" + markdownEscaped(bundle.caption, "\"\\") +
         "\")\n";
}

}  // namespace collide::report
