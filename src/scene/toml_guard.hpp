#pragma once
// Guards toml++ 3.3 (Debian 12) against its own undefined behaviour: its test for non-ASCII
// whitespace reaches __builtin_unreachable() for code points U+00A1..U+0499 and U+FB26..U+FEFE
// (é, ö, μ, Cyrillic, ...) wherever its lexer asks whether a character is whitespace, which for
// malformed text can be anywhere. Found by fuzzing. So toml++ only ever sees ASCII: text in strings
// is re-written with \u escapes (the same string once parsed), comments lose their accents, and a
// non-ASCII character anywhere else is refused with its position.
#include <string>
#include <string_view>

namespace collide::scene::detail {

// `text` with every non-ASCII character escaped, as described above. A leading UTF-8 byte order
// mark is dropped. Throws SceneError "<where>:line:column: ..." for a non-ASCII character outside
// strings and comments, or for bytes that are not UTF-8. `where` names the source ("scene.toml").
std::string asciiForToml(std::string_view text, const std::string& where);

// Like asciiForToml, but returns false instead of throwing (for values that may be bare words).
bool tryAsciiForToml(std::string_view text, std::string& out);

}  // namespace collide::scene::detail
