#include "text/glued_words.hpp"

#include <algorithm>

#include "text/line_breaks.hpp"
#include "text/number_marks.hpp"
#include "text/text_wrap.hpp"

namespace collide::text::glue {
namespace {

// The words of `text`: the pieces between its spaces (empty ones where spaces run together), and
// a piece parted after a closed-up mark ("kg·m/s，" | "当前(1.05,"), joined to the next with
// nothing, so a number, vector or unit before the mark is glued and broken as in any script.
std::vector<Word> textWords(std::string_view text) {
  std::vector<Word> words;
  std::string_view joiner;  // before the next word
  std::size_t start = 0;
  for (std::size_t at = 0; at <= text.size();) {
    if (at == text.size() || text[at] == ' ') {
      words.push_back(
          {std::string(text.substr(start, at - start)), std::string(joiner), {}, start});
      joiner = " ";
      start = ++at;
      continue;
    }
    const std::size_t mark = closedUpMarkBytes(text, at);
    if (mark > 0 && at + mark < text.size() && text[at + mark] != ' ') {
      words.push_back(
          {std::string(text.substr(start, at + mark - start)), std::string(joiner), {}, start});
      joiner = {};
      start = at += mark;
      continue;
    }
    ++at;
  }
  return words;
}

}  // namespace

std::vector<GluedWord> partedAt(const GluedWord& word, Joint at) {
  std::vector<GluedWord> out{{{word.pieces.front()}, {}, {}, word.joiner, {word.starts.front()}}};
  for (std::size_t k = 1; k < word.pieces.size(); ++k) {
    const Joint joint = word.joints[k - 1];
    if (joint == at || (at == Joint::kVectorUnit && joint == Joint::kDirection)) {
      out.push_back({{word.pieces[k]}, {}, {}, word.joiners[k - 1], {word.starts[k]}});
    } else {
      out.back().pieces.push_back(word.pieces[k]);
      out.back().joints.push_back(word.joints[k - 1]);
      out.back().joiners.push_back(word.joiners[k - 1]);
      out.back().starts.push_back(word.starts[k]);
    }
  }
  return out;
}

std::vector<GluedWord> gluedWords(std::string_view text) {
  std::vector<GluedWord> glued;
  int depth = 0;  // brackets open before the word
  for (const Word& next : textWords(text)) {
    const std::string_view word = next.text;
    const std::string last = glued.empty() ? std::string() : glued.back().text();
    const bool in_vector = depth > 0 && (startsWithDigit(word) || startsWithSign(word));
    // A sign holds to what stands before it ("t = −1.5 s"), but not across a closed-up mark:
    // "m/s，−143°" is the next item of a list, which may start a line; nor a vector's component
    // to the one before it ("(0.229," | "−0.00567)"), parted like any other component.
    // A direction after its speed ("v₁′ = 1.98 m/s, 2°"; "m/s，2°" too): one quantity.
    const bool direction =
        !glued.empty() && glued.back().pieces.size() > 1 && endsWithListMark(last) && isAngle(word);
    const bool next_component = in_vector && endsWithListMark(last);
    const bool held =
        !glued.empty() && !direction &&
        (last.empty() || last.back() == '=' || endsWithDigit(last) || word.starts_with("=") ||
         word.empty() || (startsWithSign(word) && !next.joiner.empty() && !next_component));
    depth = std::max(0, depth + bracketsOpened(word));
    const bool unit = !held && !in_vector && endsWithNumberInBrackets(last);
    const bool loose = !glued.empty() && !held && !in_vector && !unit && !direction &&
                       startsWithDigit(word) && last.back() != ',';
    if (held || loose || unit || direction || (in_vector && !glued.empty())) {
      glued.back().pieces.emplace_back(word);
      glued.back().joints.push_back(held        ? Joint::kHeld
                                    : loose     ? Joint::kLoose
                                    : unit      ? Joint::kVectorUnit
                                    : direction ? Joint::kDirection
                                                : Joint::kInVector);
      glued.back().joiners.push_back(next.joiner);
      glued.back().starts.push_back(next.start);
    } else {
      glued.push_back({{std::string(word)}, {}, {}, next.joiner, {next.start}});
    }
  }
  return glued;
}

std::vector<std::size_t> pieceEnds(const Word& word) {
  std::vector<std::size_t> ends;
  for (const std::size_t at : text::ideographicLineBreaks(word.text)) {
    if (std::find(word.unbreakable.begin(), word.unbreakable.end(), at) == word.unbreakable.end())
      ends.push_back(at);
  }
  ends.push_back(word.text.size());
  return ends;
}

}  // namespace collide::text::glue
