#pragma once
// What a teacher pastes into lecture notes beside a picture: a LaTeX figure environment (--latex,
// NAME.tex) or a Markdown image line (--markdown, NAME.md), with the caption and the alt text.
#include <optional>
#include <string>

namespace collide::report {

struct FigureBundle {
  std::string image_path;          // the picture as written; the bundle names its file alone
  std::string caption;             // one sentence, e.g. "Worked example at t = 2.500 s."
  std::string alt_text;            // what the picture shows, for readers who cannot see it
  std::optional<double> width_cm;  // the printed width, when the picture has one
  // The working beside the picture (--working): LaTeX (amsmath align*) after the figure, and
  // Markdown with $…$ math after the image line; empty: none (src/working writes both).
  std::string working_latex;
  std::string working_markdown;
};

// A figure environment for LaTeX: \includegraphics of the picture (at its printed width, else the
// line width), \caption, a \label from the file name, and the alt text as a comment above it.
// Text is escaped for LaTeX; Greek letters, sub- and superscripts and signs become math. The
// working, when the bundle has one, follows the figure.
std::string latexFigure(const FigureBundle& bundle);

// "![alt text](file "caption")" and a newline; the working, when the bundle has one, after a
// blank line.
std::string markdownFigure(const FigureBundle& bundle);

// Whether LaTeX can name the file `image_path` in \includegraphics: no character that TeX reads
// as markup ("\{}%#$&^~") or that ends its line (a control character). The caller refuses
// --latex otherwise, before any work.
bool latexNamesFile(const std::string& image_path);

// Text as one line of plain characters: every control character (a CR or LF that would end a
// LaTeX comment or a Markdown line, an ESC, ...) and U+2028/U+2029 become a space; bytes that
// are not UTF-8 become U+FFFD.
std::string oneLineText(const std::string& text);

}  // namespace collide::report
