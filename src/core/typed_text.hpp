#pragma once
// What the user typed, shown back in a one-line message: control characters escaped (a newline
// in a --set value must not split the message), cut to a length counted in characters (UTF-8 code
// points, not bytes: 33 Cyrillic letters are 33 characters), so a 1 MiB value costs one line.
#include <cstddef>
#include <string>
#include <string_view>

namespace collide::core {

// Characters in UTF-8 `text`: bytes that do not continue a multi-byte sequence.
std::size_t utf8Length(std::string_view text);

// `text` with \n, \r, \t as those escapes and any other control character (and DEL) as \xHH, cut
// after `max_characters` characters of the original with "..." added.
std::string echoTyped(std::string_view text, std::size_t max_characters = 80);

}  // namespace collide::core
