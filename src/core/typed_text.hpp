#pragma once
// What the user typed, shown back in a one-line message: control characters escaped (a newline
// in a --set value must not split the message, an ESC must not reach the terminal), cut to a
// length counted in characters (UTF-8 code points, not bytes: 33 Cyrillic letters are 33
// characters), so a 1 MiB value costs one line. And the UTF-8 checks every text from a user
// passes: what is a character, what is a control or a non-character.
#include <cstddef>
#include <string>
#include <string_view>

namespace collide::core {

// Characters in UTF-8 `text`: bytes that do not continue a multi-byte sequence.
std::size_t utf8Length(std::string_view text);

// Decodes the UTF-8 sequence at text[i] into `code_point`; returns its length in bytes, or 0 for
// bytes that are not UTF-8 there (a stray continuation byte, an overlong form, a surrogate, a
// value past U+10FFFF, a sequence cut short).
std::size_t decodeUtf8(std::string_view text, std::size_t i, char32_t& code_point);

// U+0000..U+001F, U+007F..U+009F: the C0 and C1 control characters and DEL.
bool isControlCharacter(char32_t code_point);

// The Unicode non-characters: U+FDD0..U+FDEF and the last two code points of every plane (U+FFFE,
// U+FFFF, U+1FFFE, ..., U+10FFFF). Never meant to be interchanged; fonts, PDF and XML refuse them.
bool isNonCharacter(char32_t code_point);

// "U+001B", "U+FFFE", "U+10FFFF": a code point as Unicode names it.
std::string codePointName(char32_t code_point);

// `text` with \n, \r, \t as those escapes, any other control character (C0, DEL, C1) and any
// non-character as \xHH (one byte) or \u{HHHH}, and bytes that are not UTF-8 as \xHH, cut after
// `max_characters` characters of the original with "..." added.
std::string echoTyped(std::string_view text, std::size_t max_characters = 80);

}  // namespace collide::core
