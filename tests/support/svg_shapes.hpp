#pragma once
// Reads the painted shapes of an SVG document (as Cairo writes one) with libxml2: each element
// with a path, its fill and stroke colours and the bounding box of its path's points; each
// <text> element with its characters; and how many glyph outlines (<symbol>, <use>) it holds.
#include <optional>
#include <string>
#include <vector>

namespace collide::test {

struct SvgColor {
  double r = 0, g = 0, b = 0;  // [0, 1]
};

struct SvgShape {
  std::string element;           // "path", ...
  std::optional<SvgColor> fill;  // none: fill:none or not painted
  std::optional<SvgColor> stroke;
  double stroke_opacity = 1.0;            // its style's stroke-opacity; 1 when absent
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // bounding box of the path's points, SVG user units
};

struct SvgText {
  std::string content;        // all its characters, as a viewer selects them (UTF-8)
  std::string font_family;    // the attribute as written
  std::string fill;           // the attribute as written, e.g. "#1a1a1a"
  double fill_opacity = 1.0;  // the fill-opacity attribute; 1 when absent
  double x = 0, y = 0;        // its first glyph's position, SVG user units
};

struct SvgDocument {
  std::string width, height;     // the root's attributes as written, e.g. "480pt"
  std::vector<SvgShape> shapes;  // painted elements outside <defs>, in document order
  std::vector<SvgText> texts;    // <text> elements, in document order
  int glyph_outlines = 0;        // <symbol> and <use> elements: text drawn as shapes
};

// Parses `text`; fails the calling test (and returns nothing) if it is not well-formed XML with
// an <svg> root.
std::optional<SvgDocument> readSvg(const std::string& text);

bool sameColor(const SvgColor& a, double r, double g, double b, double tolerance = 1e-3);

}  // namespace collide::test
