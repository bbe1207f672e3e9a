#include "svg_shapes.hpp"

#include <gtest/gtest.h>
#include <libxml/parser.h>
#include <libxml/tree.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace collide::test {
namespace {

std::string attribute(xmlNode* node, const char* name) {
  xmlChar* value = xmlGetProp(node, reinterpret_cast<const xmlChar*>(name));
  if (value == nullptr) return {};
  std::string out(reinterpret_cast<const char*>(value));
  xmlFree(value);
  return out;
}

// "fill:rgb(20%,40%,80%)" in a style attribute; none when absent or "none".
std::optional<SvgColor> styleColor(const std::string& style, const std::string& property) {
  std::size_t at = 0;
  while ((at = style.find(property + ":", at)) != std::string::npos) {
    // A whole property name: at the start or after ';' or ' '.
    if (at == 0 || style[at - 1] == ';' || style[at - 1] == ' ') break;
    at += property.size();
  }
  if (at == std::string::npos) return std::nullopt;
  const std::string value = style.substr(at + property.size() + 1);
  if (value.rfind("rgb(", 0) != 0) return std::nullopt;
  SvgColor c;
  const char* p = value.c_str() + 4;
  double* channels[3] = {&c.r, &c.g, &c.b};
  for (double* channel : channels) {
    char* end = nullptr;
    *channel = std::strtod(p, &end) / 100.0;  // Cairo writes percentages
    p = end + 2;                              // past "%," (or "%)")
  }
  return c;
}

// "stroke-opacity:0.5" in a style attribute; 1 when absent.
double styleNumber(const std::string& style, const std::string& property) {
  std::size_t at = 0;
  while ((at = style.find(property + ":", at)) != std::string::npos) {
    if (at == 0 || style[at - 1] == ';' || style[at - 1] == ' ') break;
    at += property.size();
  }
  if (at == std::string::npos) return 1.0;
  return std::strtod(style.c_str() + at + property.size() + 1, nullptr);
}

// Bounding box of the coordinates in a path's "d" (absolute M, L, C, Z only, as Cairo writes).
bool pathBox(const std::string& d, SvgShape& shape) {
  double lo_x = std::numeric_limits<double>::infinity(), lo_y = lo_x, hi_x = -lo_x, hi_y = -lo_x;
  const char* p = d.c_str();
  bool any = false;
  while (*p != '\0') {
    if (std::isalpha(static_cast<unsigned char>(*p)) || *p == ' ' || *p == ',') {
      ++p;
      continue;
    }
    char* end = nullptr;
    const double x = std::strtod(p, &end);
    if (end == p) return false;
    p = end;
    while (*p == ' ' || *p == ',') ++p;
    const double y = std::strtod(p, &end);
    if (end == p) return false;
    p = end;
    lo_x = std::min(lo_x, x), hi_x = std::max(hi_x, x);
    lo_y = std::min(lo_y, y), hi_y = std::max(hi_y, y);
    any = true;
  }
  shape.x0 = lo_x, shape.y0 = lo_y, shape.x1 = hi_x, shape.y1 = hi_y;
  return any;
}

// The first number of a coordinate attribute ("12.5" or "12.5 20"); 0 when absent.
double firstNumber(const std::string& value) {
  return value.empty() ? 0.0 : std::strtod(value.c_str(), nullptr);
}

SvgText readText(xmlNode* node) {
  SvgText text;
  xmlChar* content = xmlNodeGetContent(node);  // every descendant's characters, in order
  if (content != nullptr) {
    text.content = reinterpret_cast<const char*>(content);
    xmlFree(content);
  }
  text.font_family = attribute(node, "font-family");
  text.fill = attribute(node, "fill");
  const std::string fill_opacity = attribute(node, "fill-opacity");
  if (!fill_opacity.empty()) text.fill_opacity = std::strtod(fill_opacity.c_str(), nullptr);
  xmlNode* where = node;  // the position is the text's, or its first <tspan>'s
  if (attribute(node, "x").empty()) {
    for (xmlNode* child = node->children; child != nullptr; child = child->next) {
      if (child->type == XML_ELEMENT_NODE) {
        where = child;
        break;
      }
    }
  }
  text.x = firstNumber(attribute(where, "x"));
  text.y = firstNumber(attribute(where, "y"));
  return text;
}

void collect(xmlNode* node, SvgDocument& out) {
  for (; node != nullptr; node = node->next) {
    if (node->type != XML_ELEMENT_NODE) continue;
    const std::string name = reinterpret_cast<const char*>(node->name);
    if (name == "symbol" || name == "use") ++out.glyph_outlines;
    if (name == "text") {
      out.texts.push_back(readText(node));
      continue;
    }
    if (name == "defs") {  // glyph outlines, clip paths: not painted where they stand
      SvgDocument unpainted;
      collect(node->children, unpainted);
      out.glyph_outlines += unpainted.glyph_outlines;
      continue;
    }
    if (name == "path") {
      SvgShape shape;
      shape.element = name;
      const std::string style = attribute(node, "style");
      shape.fill = styleColor(style, "fill");
      shape.stroke = styleColor(style, "stroke");
      shape.stroke_opacity = styleNumber(style, "stroke-opacity");
      if (pathBox(attribute(node, "d"), shape)) out.shapes.push_back(shape);
    }
    collect(node->children, out);
  }
}

}  // namespace

std::optional<SvgDocument> readSvg(const std::string& text) {
  xmlDoc* doc = xmlReadMemory(text.data(), static_cast<int>(text.size()), "figure.svg", nullptr,
                              XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING);
  if (doc == nullptr) {
    ADD_FAILURE() << "not well-formed XML";
    return std::nullopt;
  }
  xmlNode* root = xmlDocGetRootElement(doc);
  if (root == nullptr || std::string(reinterpret_cast<const char*>(root->name)) != "svg") {
    xmlFreeDoc(doc);
    ADD_FAILURE() << "no <svg> root element";
    return std::nullopt;
  }
  SvgDocument svg;
  svg.width = attribute(root, "width");
  svg.height = attribute(root, "height");
  collect(root->children, svg);
  xmlFreeDoc(doc);
  return svg;
}

bool sameColor(const SvgColor& a, double r, double g, double b, double tolerance) {
  return std::abs(a.r - r) <= tolerance && std::abs(a.g - g) <= tolerance &&
         std::abs(a.b - b) <= tolerance;
}

}  // namespace collide::test
