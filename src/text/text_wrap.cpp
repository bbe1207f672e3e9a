#include "text/text_wrap.hpp"

#include <algorithm>
#include <cctype>

#include "text/glued_words.hpp"
#include "text/line_breaks.hpp"
#include "text/number_marks.hpp"

namespace collide::text {
namespace {

using glue::GluedWord;
using glue::gluedWords;
using glue::Joint;
using glue::partedAt;
using glue::pieceEnds;
using glue::Word;

// `part`, a vector and its unit wider than a line, parted inside its vector only, where each
// piece fits a line: the unit keeps its vector's last component ("(0.229," | "−0.00567) kg·m/s")
// rather than stand alone on a line under the vector, where it reads as the unit of nothing.
// Adds the pieces to `out`; false (nothing added) where the part holds no vector and unit, or a
// piece would still be wider than a line.
bool addVectorKeepingUnit(const GluedWord& part, double size_px, double max_width_px,
                          const TextWidth& width, std::vector<Word>& out) {
  const auto holds = [&](Joint joint) {
    return std::find(part.joints.begin(), part.joints.end(), joint) != part.joints.end();
  };
  if (!holds(Joint::kVectorUnit) || !holds(Joint::kInVector)) return false;
  const std::vector<GluedWord> pieces = partedAt(part, Joint::kInVector);
  for (const GluedWord& piece : pieces) {
    if (width(piece.text(), size_px) > max_width_px) return false;
  }
  for (const GluedWord& piece : pieces) {
    out.push_back({piece.text(), piece.joiner, piece.closedJoints(), piece.starts.front()});
  }
  return true;
}

// The words that stand alone when `word` is wider than a line: parted at its loose joints, so a
// narrow column breaks "Imagen estroboscópica: 2 imágenes" before the "2" instead of cutting
// the line short; a vector and its unit still wider than a line parted inside the vector, the
// unit with its last component, where each piece fits (addVectorKeepingUnit); else a part still
// wider than a line parted between a vector and its unit, and one still wider inside its
// vectors too.
void addLooseWords(const GluedWord& word, Joint at, double size_px, double max_width_px,
                   const TextWidth& width, std::vector<Word>& out) {
  for (const GluedWord& part : partedAt(word, at)) {
    if (at == Joint::kInVector || width(part.text(), size_px) <= max_width_px) {
      out.push_back({part.text(), part.joiner, part.closedJoints(), part.starts.front()});
      continue;
    }
    if (at == Joint::kLoose && addVectorKeepingUnit(part, size_px, max_width_px, width, out)) {
      continue;
    }
    addLooseWords(part, at == Joint::kLoose ? Joint::kVectorUnit : Joint::kInVector, size_px,
                  max_width_px, width, out);
  }
}

// A word wider than any line, parted between its characters (text::characterBreaks) into lines
// that each hold as much of it as fits (at least one character), as CSS's overflow-wrap parts
// one: the rest of a word is worth more than an ellipsis.
std::vector<std::string> partedWord(const std::string& word, double size_px, double max_width_px,
                                    const TextWidth& width) {
  std::vector<std::size_t> ends = text::characterBreaks(word);
  ends.push_back(word.size());
  std::vector<std::string> parts;
  std::size_t from = 0, fitting = 0;  // fitting: the end of the longest part that fits so far
  for (std::size_t k = 0; k < ends.size(); ++k) {
    if (fitting > from && width(word.substr(from, ends[k] - from), size_px) > max_width_px) {
      parts.push_back(word.substr(from, fitting - from));
      from = fitting;
    }
    fitting = ends[k];
  }
  parts.push_back(word.substr(from));
  return parts;
}

// What a line is filled with: a word, or a piece of a Chinese or Japanese word where UAX #14
// breaks it, with what joins it to the one before it. `alone`: a part of a word wider than any
// line, on a line of its own.
struct Token {
  std::string text;
  std::string joiner;
  bool alone = false;
};

// The tokens of the glued words: each word whole unless wider than a line (then parted at its
// loose joints, then inside its vectors), Chinese and Japanese words also where UAX #14 allows
// (never at a glued joint), a piece wider than any line parted between its characters.
std::vector<Token> lineTokens(const std::vector<GluedWord>& glued, double size_px,
                              double max_width_px, const TextWidth& width) {
  std::vector<Word> words;
  for (const GluedWord& word : glued) {
    const std::string whole = word.text();
    if (word.pieces.size() > 1 && width(whole, size_px) > max_width_px) {
      addLooseWords(word, Joint::kLoose, size_px, max_width_px, width, words);
    } else {
      words.push_back({whole, word.joiner, word.closedJoints(), word.starts.front()});
    }
  }
  std::vector<Token> tokens;
  for (const Word& word : words) {
    std::size_t piece_start = 0;
    for (const std::size_t piece_end : pieceEnds(word)) {
      std::string piece = word.text.substr(piece_start, piece_end - piece_start);
      const std::string joiner = piece_start == 0 ? word.joiner : "";
      if (width(piece, size_px) <= max_width_px) {
        tokens.push_back({std::move(piece), joiner, false});
      } else {
        for (std::string& part : partedWord(piece, size_px, max_width_px, width))
          tokens.push_back({std::move(part), "", true});
      }
      piece_start = piece_end;
    }
  }
  return tokens;
}

// A line as the tokens it holds, in order; `whole`: made of whole tokens that fit (not a part of
// a word wider than any line).
struct TokenLine {
  std::vector<std::size_t> tokens;
  bool whole = true;
};

std::string lineText(const std::vector<Token>& tokens, const std::vector<std::size_t>& line) {
  std::string out;
  for (std::size_t k = 0; k < line.size(); ++k)
    out += (k > 0 ? tokens[line[k]].joiner : "") + tokens[line[k]].text;
  return out;
}

// The line of items `line` (indices into texts), each after its joiner but the first.
std::string lineOf(const std::vector<std::string>& texts, const std::vector<std::string>& joiners,
                   const std::vector<std::size_t>& line) {
  std::string out;
  for (std::size_t k = 0; k < line.size(); ++k)
    out += (k > 0 ? joiners[line[k]] : "") + texts[line[k]];
  return out;
}

// A number alone, with its unit and the marks after it ("0°", "−143°，", "1.38 J,"): what should
// not stand alone on the last line of a list.
bool isBareQuantity(std::string_view text) {
  return (startsWithDigit(text) || startsWithSign(text)) &&
         std::count(text.begin(), text.end(), ' ') <= 1;
}

// A list's last item alone on a line, a bare quantity after a list mark ("v₁ = 0 m/s, v₂ = 200
// m/s," | "0°"), takes the item before it onto its line where both fit there ("v₁ = 0 m/s," |
// "v₂ = 200 m/s, 0°"): a number with its unit never stands alone where a better break exists.
// `texts` and `joiners`: the items a line is filled with; each line holds item indices.
void keepListEndsCompany(const std::vector<std::string>& texts,
                         const std::vector<std::string>& joiners,
                         std::vector<std::vector<std::size_t>>& lines,
                         const std::vector<bool>& movable, double size_px, double max_width_px,
                         const TextWidth& width) {
  for (std::size_t k = 1; k < lines.size(); ++k) {
    std::vector<std::size_t>& before = lines[k - 1];
    std::vector<std::size_t>& alone = lines[k];
    if (alone.size() != 1 || before.size() < 2 || !movable[k] || !movable[k - 1]) continue;
    const std::size_t item = alone.front(), moved = before.back();
    if (!isBareQuantity(texts[item]) || !endsWithListMark(texts[before[before.size() - 2]]) ||
        !endsWithListMark(texts[moved]) || isBareQuantity(texts[moved])) {
      continue;
    }
    if (width(texts[moved] + joiners[item] + texts[item], size_px) > max_width_px) continue;
    before.pop_back();
    alone.insert(alone.begin(), moved);
  }
}

// Splits `text` into lines of at most max_width_px where it can: breaks at spaces, never between
// a number and its unit nor next to "=" (so "1.38 J" and "t = 1.5 s" stay whole), and inside a
// vector ("(2,00; 0)"), between a word and the number after it ("collisions: 76") or between a
// vector and its unit only where they do not fit on a line together (a vector wider than a line
// breaks after a comma, "now" | "(0.00419," | "0.00242) kg"), and inside Chinese and Japanese
// runs where UAX #14 allows, never inside what is glued (their marks "，" part words as spaces do).
std::vector<std::string> wrapWords(std::string_view text, double size_px, double max_width_px,
                                   const TextWidth& width) {
  const std::vector<Token> tokens = lineTokens(gluedWords(text), size_px, max_width_px, width);
  std::vector<std::vector<std::size_t>> lines;
  std::vector<bool> whole;
  for (std::size_t t = 0; t < tokens.size(); ++t) {
    const bool joins = !lines.empty() && !tokens[t].alone &&
                       width(lineText(tokens, lines.back()) + tokens[t].joiner + tokens[t].text,
                             size_px) <= max_width_px;
    if (joins) {
      lines.back().push_back(t);
    } else {
      lines.push_back({t});
      whole.push_back(!tokens[t].alone);
    }
  }
  std::vector<std::string> texts, joiners;
  for (const Token& token : tokens) {
    texts.push_back(token.text);
    joiners.push_back(token.joiner);
  }
  keepListEndsCompany(texts, joiners, lines, whole, size_px, max_width_px, width);
  std::vector<std::string> out;
  for (const std::vector<std::size_t>& line : lines) {
    out.push_back(lineText(tokens, line));
    // A clause gap ("a   b") at a break leaves no spaces at the line's end.
    while (out.back().ends_with(' ')) out.back().pop_back();
  }
  return out;
}

// How a text is parted before it is broken into words, outermost first: at its clause gaps
// ("   ", "; " outside brackets), then inside a clause at ", " outside brackets ("Σp: start (1.36,
// 0) kg·m/s, now (0.25, −0.59) kg·m/s" parts before "now", never inside "(1.36, 0)"), then at
// spaces (wrapWords).
enum class Parting { kClauses, kCommas, kWords };

// A text's pieces at one parting, each with what joins it to the piece before it on a line:
// "   " between clauses, one space after a "; " or ", " (the mark stays with the piece before).
struct Piece {
  std::string text;
  std::string joiner;
};

std::vector<Piece> piecesOf(std::string_view text, Parting parting) {
  std::vector<Piece> pieces;
  std::string joiner;
  std::size_t start = 0, depth = 0;
  for (std::size_t at = 0; at < text.size(); ++at) {
    const char c = text[at];
    if (c == '(' || c == '[') ++depth;
    if ((c == ')' || c == ']') && depth > 0) --depth;
    // Only a space, ';' or ',' can start a parting: the other characters skip the comparisons.
    if (c != ' ' && c != ';' && c != ',') continue;
    std::size_t mark = 0, gap = 0;  // bytes of the mark kept on the left piece, of space dropped
    if (parting == Parting::kClauses && text.substr(at, 3) == "   ") {
      gap = 3;
    } else if (parting == Parting::kClauses && depth == 0 && text.substr(at, 2) == "; ") {
      // Not inside brackets: "; " also parts a vector's components where the decimal sign is a
      // comma, "(2,00; 0)".
      mark = 1, gap = 1;
    } else if (parting == Parting::kCommas && depth == 0 && text.substr(at, 2) == ", " &&
               !isAngle(text.substr(at + 2, text.find(' ', at + 2) - (at + 2)))) {
      // Not before a direction: "v = 1.98 m/s, 2°" is one quantity.
      mark = 1, gap = 1;
    }
    if (gap == 0) continue;
    pieces.push_back({std::string(text.substr(start, at + mark - start)), joiner});
    joiner = mark > 0 ? " " : "   ";
    start = at + mark + gap;
    at = start - 1;
  }
  pieces.push_back({std::string(text.substr(start)), joiner});
  return pieces;
}

// `text` in lines at one parting: its pieces joined on a line while they fit; a piece wider than a
// line is wrapped at the next parting on lines of its own, so each part of a readout stays
// whole where it fits even when another part must break ("collisions: 32, last e = 0.8" on one
// line, not "... last" and "e = 0.8 ..." because the momentum after it is long).
std::vector<std::string> wrapParted(std::string_view text, Parting parting, double size_px,
                                    double max_width_px, const TextWidth& width) {
  if (parting == Parting::kWords) return wrapWords(text, size_px, max_width_px, width);
  const Parting finer = parting == Parting::kClauses ? Parting::kCommas : Parting::kWords;
  const std::vector<Piece> pieces = piecesOf(text, parting);
  if (pieces.size() < 2) return wrapParted(text, finer, size_px, max_width_px, width);
  // The items lines are made of: the pieces, then the lines a piece wider than a line is wrapped
  // into at the finer parting (each a line of its own, `movable` false).
  std::vector<std::string> texts, joiners;
  for (const Piece& piece : pieces) {
    texts.push_back(piece.text);
    joiners.push_back(piece.joiner);
  }
  std::vector<std::vector<std::size_t>> lines;
  std::vector<bool> movable;
  bool last_line_open = false;  // whether the last line ends with a whole piece another may join
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    if (width(texts[p], size_px) <= max_width_px) {
      const bool joins =
          last_line_open && width(lineOf(texts, joiners, lines.back()) + joiners[p] + texts[p],
                                  size_px) <= max_width_px;
      if (joins) {
        lines.back().push_back(p);
      } else {
        lines.push_back({p});
        movable.push_back(true);
      }
      last_line_open = true;
    } else {
      for (std::string& line : wrapParted(texts[p], finer, size_px, max_width_px, width)) {
        lines.push_back({texts.size()});
        movable.push_back(false);
        texts.push_back(std::move(line));
        joiners.emplace_back();
      }
      last_line_open = false;
    }
  }
  keepListEndsCompany(texts, joiners, lines, movable, size_px, max_width_px, width);
  std::vector<std::string> out;
  for (const std::vector<std::size_t>& line : lines) out.push_back(lineOf(texts, joiners, line));
  return out;
}

}  // namespace

std::size_t closedUpMarkBytes(std::string_view text, std::size_t at) {
  if (at >= text.size()) return 0;
  const char32_t c = utf8CodePointAt(text, at);
  const bool mark =
      c == U'\u3001' || c == U'\u3002' || c == U'\uFF0C' || c == U'\uFF1A' || c == U'\uFF1B';
  return mark ? 3 : 0;
}

std::vector<std::string> wrapText(std::string_view text, double size_px, double max_width_px,
                                  const TextWidth& width) {
  if (text.empty()) return {};
  std::vector<std::string> lines =
      wrapParted(text, Parting::kClauses, size_px, max_width_px, width);
  // A part wider than a line breaks on lines of its own, which may take a line more than words
  // filling every line; where room is counted in lines (a side column under the info, a printed
  // figure) that line would cut the text below, so parts stay whole only where it costs no line.
  const std::vector<Piece> clauses = piecesOf(text, Parting::kClauses);
  const bool every_clause_fits = std::all_of(clauses.begin(), clauses.end(), [&](const Piece& c) {
    return width(c.text, size_px) <= max_width_px;
  });
  if (!every_clause_fits) {
    std::vector<std::string> filled = wrapWords(text, size_px, max_width_px, width);
    if (filled.size() < lines.size()) lines = std::move(filled);
  }
  for (std::string& line : lines) {
    while (line.ends_with(' ')) line.pop_back();
    line.erase(0, line.find_first_not_of(' ') == std::string::npos ? line.size()
                                                                   : line.find_first_not_of(' '));
  }
  return lines;
}

double widestUnbrokenPx(std::string_view text, double size_px, const TextWidth& width) {
  double widest_px = 0.0;
  for (const GluedWord& glued : gluedWords(text)) {
    for (const GluedWord& part : partedAt(glued, Joint::kLoose)) {
      // A vector is parted only where the part that holds it is wider than a line (lineTokens),
      // though Chinese and Japanese may break its part between their characters, before it
      // ("当前" | "(1, 2) kg").
      const bool vector =
          std::find(part.joints.begin(), part.joints.end(), Joint::kInVector) != part.joints.end();
      const Word word{part.text(), part.joiner, part.closedJoints()};
      std::size_t piece_start = 0;
      for (const std::size_t piece_end : pieceEnds(word)) {
        if (vector && piece_end > part.pieces.front().size()) break;
        widest_px = std::max(
            widest_px, width(word.text.substr(piece_start, piece_end - piece_start), size_px));
        piece_start = piece_end;
      }
      if (vector) widest_px = std::max(widest_px, width(word.text.substr(piece_start), size_px));
    }
  }
  return widest_px;
}

std::vector<std::string> captionLinesBesideScale(std::string_view caption, double size_px,
                                                 double caption_width_px, double scale_room_px,
                                                 const TextWidth& width) {
  std::vector<std::string> lines = wrapText(caption, size_px, caption_width_px, width);
  if (scale_room_px > 0.0 && !lines.empty() &&
      width(lines.back(), size_px) > caption_width_px - scale_room_px) {
    lines = wrapText(caption, size_px, std::max(0.0, caption_width_px - scale_room_px), width);
  }
  return lines;
}

}  // namespace collide::text
