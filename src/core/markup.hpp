// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <string_view>

namespace collide::core {

// Text made safe for XML and HTML, in element content and in attribute values (quoted either
// way): & < > " ' become character references, everything else is kept byte for byte. One rule
// for every markup collide writes (SVG figures, MathML, the lesson page), so that a name typed
// in a scene reads the same in each.
void appendMarkupEscaped(std::string& out, std::string_view text);
std::string markupEscaped(std::string_view text);

}  // namespace collide::core
