// SPDX-License-Identifier: MIT
#pragma once
// SVG text placed character by character, for a rasteriser that does not: librsvg 2.54 takes one
// x per <text> or <tspan> and lays the rest of the string out itself (its devel-docs/
// text-layout.md), where SVG 1.1 and 2 give each character of a list of x values its own.
#include <string>

namespace collide::test {

// `svg` with every <tspan> whose x is a list split into one <tspan> per character at its own x
// (the other attributes as they were): the document as a viewer that honours the lists draws it.
// Fails the calling test (and returns "") if the XML is not well formed or a list does not hold
// exactly one value per character.
std::string withEachCharacterPlaced(const std::string& svg);

}  // namespace collide::test
