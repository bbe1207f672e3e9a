#pragma once
// A text as line wrapping sees it (text_wrap.cpp): its words, and inside each word the pieces that
// stay on one line and how each two are joined (a number to its unit, a vector's components, a
// speed to its direction). Shared by the wrapping and the widest unbroken piece; private to the
// text module.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace collide::text::glue {

// How two pieces of a word are joined: held (a number to its unit, "1.38 J"; "=" to both sides,
// "t = 1.5 s"; a sign to its number), loose (a number after a word, "image: 2": together only
// where a line has room for both), a vector's unit after it ("(0, 0) kg·m/s") or a direction
// after its speed ("1.98 m/s, 2°": one quantity), parted only where the two are wider than a
// line, after loose joints, or inside a vector ("(2,00;" and "0)": parted only where the vector
// alone is wider than a line).
enum class Joint { kHeld, kLoose, kVectorUnit, kDirection, kInVector };

// A word as wrapping sees it: the pieces between spaces (or after a mark Chinese and Japanese
// close up, "，") that stay on one line, how each two are joined, and what stands between them.
struct GluedWord {
  std::vector<std::string> pieces;
  std::vector<Joint> joints;         // joint k is between pieces k and k + 1
  std::vector<std::string> joiners;  // " ", or "" after a closed-up mark
  std::string joiner;                // before the word on a line
  std::vector<std::size_t> starts;   // byte offset of each piece in the text it was glued from
  std::string text() const {
    std::string out = pieces.front();
    for (std::size_t k = 1; k < pieces.size(); ++k) out += joiners[k - 1] + pieces[k];
    return out;
  }
  // The byte offsets in text() of its joints with nothing between the pieces, where no line
  // may break though UAX #14 would ("碰撞次数：" | "1").
  std::vector<std::size_t> closedJoints() const {
    std::vector<std::size_t> at;
    std::size_t end = pieces.front().size();
    for (std::size_t k = 1; k < pieces.size(); ++k) {
      if (joiners[k - 1].empty()) at.push_back(end);
      end += joiners[k - 1].size() + pieces[k].size();
    }
    return at;
  }
};

// A word of a line, what joins it to the word before it on the line, and where inside it no line
// may break (GluedWord::closedJoints).
struct Word {
  std::string text;
  std::string joiner;
  std::vector<std::size_t> unbreakable;
  std::size_t start = 0;  // byte offset in the text it is a word of
};

// `word` parted at its joints of kind `at` into words, the other joints kept; at a vector's unit,
// also between a speed and its direction.
std::vector<GluedWord> partedAt(const GluedWord& word, Joint at);

// The words of `text` glued: a number to its unit and "=" to both sides (held), a number after a
// word or a unit after a vector (loose), a vector's components (in vector).
std::vector<GluedWord> gluedWords(std::string_view text);

// Where the pieces of `word` end: at the breaks UAX #14 allows in Chinese and Japanese
// (text::ideographicLineBreaks), never at a glued joint, and at its end.
std::vector<std::size_t> pieceEnds(const Word& word);

}  // namespace collide::text::glue
