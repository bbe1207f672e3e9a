#pragma once
// UTF-8 to code points and back, for text layout.
#include <string>
#include <string_view>

namespace collide::render {

// Decodes UTF-8; malformed bytes become U+FFFD.
std::u32string decodeUtf8(std::string_view text);
std::string encodeUtf8(std::u32string_view text);

}  // namespace collide::render
