#include "report/figure_bundle.hpp"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <string_view>
#include <utility>
#include <vector>

#include "core/typed_text.hpp"

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

std::string latexText(const std::string& raw) {
  const std::string text = oneLineText(raw);
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
    out += text[i];
    ++i;
  }
  return out;
}

// A comment line per line of text: nothing in it can end the comment (every other control
// character, CR among them, is a space).
std::string latexComment(const std::string& text) {
  std::string out = "% ";
  std::size_t start = 0;
  for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1) {
    out += oneLineText(text.substr(start, end - start)) + "\n% ";
  }
  return out + oneLineText(text.substr(start)) + "\n";
}

// Letters, digits and '-' of the file's stem: a \label that any LaTeX accepts.
std::string labelOf(const std::string& path) {
  std::string out;
  for (char c : std::filesystem::path(path).stem().string()) {
    out += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  }
  return "fig:" + out;
}

// One line with `special` characters backslash-escaped (CommonMark allows it for any ASCII
// punctuation); < > & also, so no HTML can start in it.
std::string markdownEscaped(const std::string& raw, const std::string& special) {
  std::string out;
  for (char c : oneLineText(raw)) {
    if (special.find(c) != std::string::npos || c == '<' || c == '>' || c == '&') out += '\\';
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
  out += bundle.working_latex.empty()
             ? "% Figure made by collide; needs \\usepackage{graphicx}.\n"
             : "% Figure and working made by collide; needs \\usepackage{graphicx,amsmath}.\n";
  out += latexComment("Alt text: " + bundle.alt_text);
  out += "\\begin{figure}[htbp]\n";
  out += "  \\centering\n";
  out += "  \\includegraphics[width=" + width + "]{" + file + "}\n";
  out += "  \\caption{" + latexText(bundle.caption) + "}\n";
  out += "  \\label{" + labelOf(bundle.image_path) + "}\n";
  out += "\\end{figure}\n";
  if (!bundle.working_latex.empty()) out += "\n" + bundle.working_latex;
  return out;
}

std::string markdownFigure(const FigureBundle& bundle) {
  const std::string file = std::filesystem::path(bundle.image_path).filename().string();
  // Spaces and parentheses in the file name would end the link: angle brackets keep it whole.
  const bool plain = file.find_first_of(" ()<>\\") == std::string::npos;
  const std::string image = "![" + markdownEscaped(bundle.alt_text, "[]\\*_`") + "](" +
                            (plain ? file : "<" + markdownEscaped(file, "\\") + ">") + " \"" +
                            markdownEscaped(bundle.caption, "\"\\") + "\")\n";
  return bundle.working_markdown.empty() ? image : image + "\n" + bundle.working_markdown;
}

bool latexNamesFile(const std::string& image_path) {
  const std::string file = std::filesystem::path(image_path).filename().string();
  for (const char c : file) {
    if (std::string_view("\\{}%#$&^~").find(c) != std::string_view::npos) return false;
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) return false;
  }
  return true;
}

std::string oneLineText(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    char32_t code_point = 0;
    const std::size_t length = core::decodeUtf8(text, i, code_point);
    if (length == 0) {
      out += "\uFFFD";
      ++i;
      continue;
    }
    const bool breaks =
        core::isControlCharacter(code_point) || code_point == 0x2028 || code_point == 0x2029;
    out += breaks ? std::string(" ") : text.substr(i, length);
    i += length;
  }
  return out;
}

}  // namespace collide::report
