// SPDX-License-Identifier: MIT
#include "svg_positions.hpp"

#include <gtest/gtest.h>
#include <libxml/parser.h>
#include <libxml/tree.h>

#include <sstream>
#include <vector>

namespace collide::test {
namespace {

const xmlChar* xml(const char* text) {
  return reinterpret_cast<const xmlChar*>(text);
}

std::vector<std::string> listValues(const std::string& list) {
  std::istringstream in(list);
  std::vector<std::string> values;
  for (std::string value; in >> value;) values.push_back(value);
  return values;
}

// UTF-8 text cut into its code points, each as its bytes.
std::vector<std::string> codePoints(const std::string& text) {
  std::vector<std::string> out;
  for (std::size_t at = 0; at < text.size();) {
    std::size_t length = 1;
    while (at + length < text.size() &&
           (static_cast<unsigned char>(text[at + length]) & 0xC0) == 0x80) {
      ++length;
    }
    out.push_back(text.substr(at, length));
    at += length;
  }
  return out;
}

// Replaces `tspan` (its x a list) with one <tspan> per character; false if the counts differ.
bool splitPositioned(xmlNode* tspan, const std::vector<std::string>& xs) {
  xmlChar* content = xmlNodeGetContent(tspan);
  const std::string text = content != nullptr ? reinterpret_cast<const char*>(content) : "";
  xmlFree(content);
  const std::vector<std::string> characters = codePoints(text);
  if (characters.size() != xs.size()) {
    ADD_FAILURE() << xs.size() << " x values for the " << characters.size() << " characters of '"
                  << text << "'";
    return false;
  }
  for (std::size_t k = 0; k < xs.size(); ++k) {
    xmlNode* one = xmlCopyNode(tspan, 2);  // the element and its attributes
    xmlSetProp(one, xml("x"), xml(xs[k].c_str()));
    xmlNodeAddContent(one, xml(characters[k].c_str()));
    xmlAddPrevSibling(tspan, one);
  }
  xmlUnlinkNode(tspan);
  xmlFreeNode(tspan);
  return true;
}

bool splitAll(xmlNode* node) {
  while (node != nullptr) {
    xmlNode* next = node->next;  // `node` may be replaced
    if (node->type == XML_ELEMENT_NODE) {
      if (xmlStrEqual(node->name, xml("tspan"))) {
        xmlChar* x = xmlGetProp(node, xml("x"));
        const std::vector<std::string> xs =
            listValues(x != nullptr ? reinterpret_cast<const char*>(x) : "");
        xmlFree(x);
        if (xs.size() > 1) {
          if (!splitPositioned(node, xs)) return false;
          node = next;
          continue;
        }
      }
      if (!splitAll(node->children)) return false;
    }
    node = next;
  }
  return true;
}

}  // namespace

std::string withEachCharacterPlaced(const std::string& svg) {
  xmlDoc* doc = xmlReadMemory(svg.data(), static_cast<int>(svg.size()), "figure.svg", nullptr,
                              XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING);
  if (doc == nullptr) {
    ADD_FAILURE() << "not well-formed XML";
    return {};
  }
  std::string out;
  if (splitAll(xmlDocGetRootElement(doc))) {
    xmlChar* bytes = nullptr;
    int size = 0;
    xmlDocDumpMemory(doc, &bytes, &size);
    out.assign(reinterpret_cast<const char*>(bytes), static_cast<std::size_t>(size));
    xmlFree(bytes);
  }
  xmlFreeDoc(doc);
  return out;
}

}  // namespace collide::test
