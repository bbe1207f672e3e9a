#include "render/text/shaper.hpp"

#include <fribidi.h>
#include <hb.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace collide::render {
namespace {

constexpr double kSubscriptDrop = 0.18;   // em below the baseline
constexpr double kSuperscriptRise = 0.4;  // em above the baseline
constexpr char32_t kPrime = U'\u2032';

// The ordinary character a sub- or superscript stands for; 0 if `c` is neither.
char32_t subscriptBase(char32_t c) {
  if (c >= 0x2080 && c <= 0x2089) return U'0' + (c - 0x2080);
  static constexpr char32_t kRest[] = {U'+', U'\u2212', U'=', U'(',      U')', 0,    U'a',
                                       U'e', U'o',      U'x', U'\u0259', U'h', U'k', U'l',
                                       U'm', U'n',      U'p', U's',      U't'};
  if (c >= 0x208A && c <= 0x209C) return kRest[c - 0x208A];
  return 0;
}

char32_t superscriptBase(char32_t c) {
  switch (c) {
    case 0x00B9:
      return U'1';
    case 0x00B2:
      return U'2';
    case 0x00B3:
      return U'3';
    case 0x2070:
      return U'0';
    case 0x2071:
      return U'i';
    case 0x207A:
      return U'+';
    case 0x207B:
      return U'\u2212';
    case 0x207F:
      return U'n';
    default:
      break;
  }
  if (c >= 0x2074 && c <= 0x2079) return U'4' + (c - 0x2074);
  return 0;
}

enum class Position { kInline, kSubscript, kSuperscript };

// Characters of one embedding level, one font and one position: shaped by one HarfBuzz call.
struct Run {
  std::size_t start = 0, end = 0;  // characters [start, end) of the line
  FriBidiLevel level = 0;
  int font = 0;
  Position position = Position::kInline;
};

// A decimal digit: ASCII, Arabic-Indic (U+0660..9) or Eastern Arabic-Indic (U+06F0..9).
bool isDigit(char32_t c) {
  return (c >= 0x0030 && c <= 0x0039) || (c >= 0x0660 && c <= 0x0669) ||
         (c >= 0x06F0 && c <= 0x06F9);
}

bool isSign(char32_t c) {
  return c == U'+' || c == U'-' || c == U'\u2212' || c == U'\u00B1';
}

constexpr char32_t kArabicLetterMark = U'\u061C';

bool isRightToLeftLetter(char32_t c) {
  return (c >= 0x0590 && c <= 0x08FF) || (c >= 0xFB1D && c <= 0xFDFF) ||
         (c >= 0xFE70 && c <= 0xFEFF);
}

bool isLatinLetter(char32_t c) {
  return (c >= U'a' && c <= U'z') || (c >= U'A' && c <= U'Z');
}

// What a quantity is written with after its first digit: digits, the decimal point, Latin and
// Greek unit letters, and the signs of units and exponents ("2.5", "1.00 kg·m/s", "67.5%"); in
// Arabic also its decimal and group signs (٫ ٬), its percent sign (٪) and the letter mark CLDR
// writes beside a sign.
bool inQuantity(char32_t c) {
  return isDigit(c) || isLatinLetter(c) || (c >= 0x0370 && c <= 0x03FF) || c == U'\u066A' ||
         c == U'\u066B' || c == U'\u066C' || c == kArabicLetterMark ||
         (c >= 0x2070 && c <= 0x209F) || c == U'.' || c == U',' || c == U'\u00B7' || c == U'/' ||
         c == U'%' || c == U'\u00B0' || c == U'\u00B5' || c == U'\u00B2' || c == U'\u00B3' ||
         c == U'\u00B9' || c == U'\u2032' || c == U'\u2033';
}

constexpr char32_t kArabicSemicolon = U'\u061B';

// Whether a number starts at `at`: a digit, or a sign before one (after the letter mark the CLDR
// Arabic minus carries).
bool numberStartsAt(const std::u32string& chars, std::size_t at) {
  if (at < chars.size() && chars[at] == kArabicLetterMark) ++at;
  if (at < chars.size() && isSign(chars[at])) ++at;
  return at < chars.size() && isDigit(chars[at]);
}

// The Arabic semicolon at `at` parts the components of a vector ("(٢٫٠٠؛ ٠)",
// docs/translations.md): a digit before it, the next number after its space.
bool partsVectorComponents(const std::u32string& chars, std::size_t at) {
  return chars[at] == kArabicSemicolon && at > 0 && isDigit(chars[at - 1]) &&
         at + 1 < chars.size() && chars[at + 1] == U' ' && numberStartsAt(chars, at + 2);
}

// Where the vector that opens at `open` ("(٢٫٠٠؛ ٠)", "(1.5, −2)") closes, one past its ")";
// 0 where no vector opens there.
std::size_t vectorEnd(const std::u32string& chars, std::size_t open) {
  if (chars[open] != U'(' || !numberStartsAt(chars, open + 1)) return 0;
  bool parted = false;
  for (std::size_t at = open + 1; at < chars.size(); ++at) {
    if (chars[at] == U')') return parted ? at + 1 : 0;
    const bool between = partsVectorComponents(chars, at) ||
                         (chars[at] == U',' && at + 1 < chars.size() && chars[at + 1] == U' ');
    parted = parted || between;
    if (!between && !inQuantity(chars[at]) && !isSign(chars[at]) && chars[at] != U' ') return 0;
  }
  return 0;
}

// The quantities of a right-to-left line that start with a sign or a digit, [start, end) each:
// "+1.00 kg·m/s" in an Arabic sentence. By the bidirectional algorithm alone their sign and unit
// would land on the wrong side of the number ("kg·m/s 1.00+"); isolated as left-to-right they
// read as in a physics book. (A quantity after a Latin letter, "v = 1.5 m/s", is already left to
// right by rule W7, and is left alone.)
std::vector<std::pair<std::size_t, std::size_t>> quantities(const std::u32string& chars) {
  std::vector<std::pair<std::size_t, std::size_t>> spans;
  const std::size_t n = chars.size();
  for (std::size_t i = 0; i < n; ++i) {
    // A sign may come after the Arabic letter mark (CLDR's Arabic minus: U+061C U+2212).
    const std::size_t mark = chars[i] == kArabicLetterMark ? 1 : 0;
    const bool signed_number =
        i + mark + 1 < n && isSign(chars[i + mark]) && isDigit(chars[i + mark + 1]);
    // A vector with its unit is one quantity: by the algorithm alone its unit would stand left
    // of it, and its components, parted by the right-to-left "؛", would swap places.
    const std::size_t vector_end = vectorEnd(chars, i);
    if (!signed_number && !isDigit(chars[i]) && vector_end == 0) continue;
    // Arabic-Indic digits are Arabic numbers to the algorithm, which rule W7 never makes left to
    // right after a Latin letter: they are isolated wherever they stand.
    const bool european =
        vector_end == 0 && chars[signed_number ? i + mark + 1 : i] <= 0x0039;  // ASCII
    if (i > 0 && inQuantity(chars[i - 1])) continue;  // inside a word or after a Latin letter
    // After a Latin letter with nothing right-to-left between ("e = 0.5"), the number is left to
    // right already (rule W7) and joins the letter's run.
    bool after_latin = false;
    // A quantity isolated before counts as neither. `formula`: where the Latin formula it ends
    // ("v₂′ = ") starts.
    const std::size_t isolated_end = spans.empty() ? 0 : spans.back().second;
    std::size_t formula = i;
    for (std::size_t k = i; k-- > isolated_end;) {
      if (isRightToLeftLetter(chars[k])) break;
      if (isLatinLetter(chars[k]) || (chars[k] >= 0x0370 && chars[k] <= 0x03FF)) after_latin = true;
      if (chars[k] != U' ') formula = k;
    }
    if (after_latin && european) continue;
    // An Arabic number after a Latin formula is isolated with it, so "v₂′ = +١٫٢٥ m/s" reads as
    // one left-to-right piece.
    const std::size_t start = after_latin ? formula : i;
    std::size_t end = vector_end > 0 ? vector_end : i + (signed_number ? mark + 1 : 1);
    while (end < n && (inQuantity(chars[end]) ||
                       (chars[end] == U' ' && end + 1 < n && isLatinLetter(chars[end + 1])))) {
      ++end;
    }
    while (end > i + 1 && (chars[end - 1] == U'.' || chars[end - 1] == U',')) --end;
    spans.emplace_back(start, end);
    i = end - 1;
  }
  return spans;
}

// The left side of a Latin formula before right-to-left words ("t = " in "t = من ٠ إلى ٤ s", the
// span of a strobe), [start, end) each, up to its "=": by the algorithm alone the "=" would take
// the direction of the sentence and stand left of the symbol ("= t").
std::vector<std::pair<std::size_t, std::size_t>> formulaSides(const std::u32string& chars) {
  std::vector<std::pair<std::size_t, std::size_t>> spans;
  for (std::size_t eq = 0; eq < chars.size(); ++eq) {
    if (chars[eq] != U'=') continue;
    std::size_t next = eq + 1;
    while (next < chars.size() && chars[next] == U' ') ++next;
    if (next == chars.size() || !isRightToLeftLetter(chars[next])) continue;
    std::size_t start = eq;
    bool latin = false;
    for (std::size_t k = eq; k-- > 0 && !isRightToLeftLetter(chars[k]) && chars[k] != U'=';) {
      latin = latin || isLatinLetter(chars[k]) || (chars[k] >= 0x0370 && chars[k] <= 0x03FF);
      if (chars[k] != U' ') start = k;
    }
    if (latin) spans.emplace_back(start, eq + 1);
  }
  return spans;
}

// The spans of a right-to-left line read left to right: its quantities and the left sides of
// its formulas before right-to-left words, in order.
std::vector<std::pair<std::size_t, std::size_t>> leftToRightSpans(const std::u32string& chars) {
  std::vector<std::pair<std::size_t, std::size_t>> spans = quantities(chars);
  for (const auto& side : formulaSides(chars)) {
    const bool inside = std::any_of(spans.begin(), spans.end(), [&](const auto& span) {
      return span.first < side.second && side.first < span.second;
    });
    if (!inside) spans.push_back(side);
  }
  std::sort(spans.begin(), spans.end());
  return spans;
}

// Embedding levels of the Unicode Bidirectional Algorithm (rules P2 to I2, and L1).
//
// The paragraph direction: in a right-to-left language, right to left when the line has a
// right-to-left letter, else left to right: a formula, a number or a unit ("v₁′ = −0.25 m/s",
// "−2", "5 m") reads as it is written in the learner's physics book, not with its minus sign
// at the right. In a left-to-right language, the first strong letter decides (a user's Arabic
// title in an English frame reads from the right).
std::vector<FriBidiLevel> embeddingLevels(const std::u32string& line, bool right_to_left) {
  FriBidiParType direction = FRIBIDI_PAR_WLTR;
  std::vector<FriBidiCharType> types(line.size());
  fribidi_get_bidi_types(reinterpret_cast<const FriBidiChar*>(line.data()),
                         static_cast<FriBidiStrIndex>(line.size()), types.data());
  if (right_to_left) {
    // Letters only: the Arabic letter mark (U+061C) that Arabic numbers carry before a minus
    // sign does not make a formula an Arabic sentence.
    const bool has_rtl_letter = std::any_of(line.begin(), line.end(), [](char32_t c) {
      return isRightToLeftLetter(c) &&
             hb_unicode_general_category(hb_unicode_funcs_get_default(), c) ==
                 HB_UNICODE_GENERAL_CATEGORY_OTHER_LETTER;
    });
    direction = has_rtl_letter ? FRIBIDI_PAR_RTL : FRIBIDI_PAR_LTR;
  }
  // The line as the algorithm sees it: quantities and the left sides of formulas in a right-to-left
  // line isolated (LRI ... PDI).
  std::u32string chars;
  std::vector<std::size_t> position;  // where each character of `line` is in `chars`
  std::size_t next = 0;
  const auto copy_to = [&](std::size_t end) {
    for (; next < end; ++next) {
      position.push_back(chars.size());
      chars.push_back(line[next]);
    }
  };
  if (direction == FRIBIDI_PAR_RTL) {
    for (const auto& [start, end] : leftToRightSpans(line)) {
      copy_to(start);
      chars.push_back(U'\u2066');  // LEFT-TO-RIGHT ISOLATE
      copy_to(end);
      chars.push_back(U'\u2069');  // POP DIRECTIONAL ISOLATE
    }
  }
  copy_to(line.size());

  const auto n = static_cast<FriBidiStrIndex>(chars.size());
  const auto* unicode = reinterpret_cast<const FriBidiChar*>(chars.data());
  types.resize(chars.size());
  std::vector<FriBidiBracketType> brackets(chars.size());
  fribidi_get_bidi_types(unicode, n, types.data());
  fribidi_get_bracket_types(unicode, n, types.data(), brackets.data());
  // The Arabic letter mark CLDR writes before a minus sign would take the sign and the digits
  // after it into a right-to-left run ("١٤٣−°"), in a left-to-right line as in a number isolated
  // in an Arabic sentence: it is only a mark here, ignored as a boundary neutral, so the sign
  // stays before its digits ("−١٤٣°").
  // A sign before Arabic-Indic digits is read as one of them (an Arabic number, whose run keeps
  // its characters in order): it stays left of its digits wherever the number stands.
  // The Arabic semicolon between the components of a vector is a right-to-left letter to the
  // algorithm, which would swap the components ("(٠ ؛٢٫٠٠)"): there it reads as left to right.
  for (std::size_t i = 0; i < chars.size(); ++i) {
    if (chars[i] == kArabicLetterMark) types[i] = FRIBIDI_TYPE_BN;
    if (partsVectorComponents(chars, i)) types[i] = FRIBIDI_TYPE_LTR;
    if (isSign(chars[i]) && i + 1 < chars.size() && isDigit(chars[i + 1]) &&
        chars[i + 1] > 0x0039) {
      types[i] = FRIBIDI_TYPE_AN;
    }
  }
  const auto paragraph_level = static_cast<FriBidiLevel>(direction == FRIBIDI_PAR_RTL ? 1 : 0);
  std::vector<FriBidiLevel> levels(chars.size(), paragraph_level);
  if (fribidi_get_par_embedding_levels_ex(types.data(), brackets.data(), n, &direction,
                                          levels.data()) == 0) {
    std::fill(levels.begin(), levels.end(), paragraph_level);
  }
  std::vector<FriBidiLevel> line_levels(line.size());
  for (std::size_t i = 0; i < line.size(); ++i) line_levels[i] = levels[position[i]];
  return line_levels;
}

// Rule L2: from the highest level down to the lowest odd one, reverse every sequence of runs at
// that level or above. Returns the runs' indices in visual order, left to right.
std::vector<std::size_t> visualOrder(const std::vector<Run>& runs) {
  std::vector<std::size_t> order(runs.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  int highest = 0, lowest_odd = 255;
  for (const Run& run : runs) {
    highest = std::max<int>(highest, run.level);
    if (run.level % 2 == 1) lowest_odd = std::min<int>(lowest_odd, run.level);
  }
  for (int level = highest; level >= lowest_odd && level > 0; --level) {
    for (std::size_t i = 0; i < order.size();) {
      if (runs[order[i]].level < level) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j < order.size() && runs[order[j]].level >= level) ++j;
      std::reverse(order.begin() + static_cast<std::ptrdiff_t>(i),
                   order.begin() + static_cast<std::ptrdiff_t>(j));
      i = j;
    }
  }
  return order;
}

// What HarfBuzz shapes: the line with its sub- and superscripts as their ordinary characters,
// each character's position and the font that draws it.
struct ShapingInput {
  std::u32string shaped;
  std::vector<Position> position;
  std::vector<int> font;
};

ShapingInput shapingInput(FontSet& fonts, const std::u32string& chars) {
  const std::size_t n = chars.size();
  ShapingInput in{chars, std::vector<Position>(n, Position::kInline), std::vector<int>(n, 0)};
  int previous = -1;
  for (std::size_t i = 0; i < n; ++i) {
    if (const char32_t base = subscriptBase(chars[i]); base != 0) {
      in.shaped[i] = base;
      in.position[i] = Position::kSubscript;
    } else if (const char32_t up = superscriptBase(chars[i]); up != 0) {
      in.shaped[i] = up;
      in.position[i] = Position::kSuperscript;
    }
    in.font[i] = previous = fonts.fontFor(in.shaped[i], previous);
    if (in.shaped[i] == kPrime && !fonts.font(in.font[i]).hasGlyph(kPrime)) in.shaped[i] = U'\'';
  }
  return in;
}

// The line cut into runs of one embedding level, font and position, in logical order.
std::vector<Run> runsOf(const ShapingInput& in, const std::vector<FriBidiLevel>& levels) {
  std::vector<Run> runs;
  for (std::size_t i = 0; i < in.shaped.size(); ++i) {
    if (runs.empty() || levels[i] != runs.back().level || in.font[i] != runs.back().font ||
        in.position[i] != runs.back().position) {
      runs.push_back({i, i + 1, levels[i], in.font[i], in.position[i]});
    } else {
      runs.back().end = i + 1;
    }
  }
  return runs;
}

// One run shaped by HarfBuzz in `buffer`, its glyphs appended to `line` from the pen position
// `pen`, which moves on by their advances. `size` is the line's pixel size, `script_size` that of
// its sub- and superscripts.
class RunShaper {
 public:
  RunShaper(FontSet& fonts, const std::u32string& shaped, int size, int script_size)
      : fonts_(fonts),
        shaped_(shaped),
        size_(size),
        script_size_(script_size),
        buffer_(hb_buffer_create()),
        language_(hb_language_from_string(fonts.languageTag().c_str(), static_cast<int>(-1))) {}
  ~RunShaper() { hb_buffer_destroy(buffer_); }
  RunShaper(const RunShaper&) = delete;
  RunShaper& operator=(const RunShaper&) = delete;

  void shape(const Run& run, double& pen, ShapedLine& line) {
    const bool rtl = run.level % 2 == 1;
    const int run_size = run.position == Position::kInline ? size_ : script_size_;
    double shift = 0.0;
    if (run.position == Position::kSubscript) shift = std::round(kSubscriptDrop * size_);
    if (run.position == Position::kSuperscript) shift = -std::round(kSuperscriptRise * size_);

    hb_buffer_clear_contents(buffer_);
    // The whole line as context, so letters join across a run's ends where they should.
    hb_buffer_add_utf32(buffer_, reinterpret_cast<const std::uint32_t*>(shaped_.data()),
                        static_cast<int>(shaped_.size()), static_cast<unsigned>(run.start),
                        static_cast<int>(run.end - run.start));
    hb_buffer_set_direction(buffer_, rtl ? HB_DIRECTION_RTL : HB_DIRECTION_LTR);
    hb_buffer_set_language(buffer_, language_);
    hb_buffer_guess_segment_properties(buffer_);
    hb_shape(fonts_.font(run.font).shapingFont(run_size), buffer_, nullptr, 0);

    unsigned count = 0;
    const hb_glyph_info_t* info = hb_buffer_get_glyph_infos(buffer_, &count);
    const hb_glyph_position_t* placed = hb_buffer_get_glyph_positions(buffer_, &count);
    cluster_starts_.clear();
    for (unsigned g = 0; g < count; ++g) cluster_starts_.push_back(info[g].cluster);
    std::sort(cluster_starts_.begin(), cluster_starts_.end());
    for (unsigned g = 0; g < count; ++g) {
      ShapedGlyph glyph;
      glyph.font = run.font;
      glyph.glyph_id = info[g].codepoint;
      glyph.pixel_size = run_size;
      glyph.x_px = pen + placed[g].x_offset / 64.0;
      glyph.shift_px = shift - placed[g].y_offset / 64.0;
      glyph.cluster_begin = info[g].cluster;
      const auto next =
          std::upper_bound(cluster_starts_.begin(), cluster_starts_.end(), info[g].cluster);
      glyph.cluster_end =
          next != cluster_starts_.end() ? *next : static_cast<std::uint32_t>(run.end);
      glyph.drawn = shaped_[info[g].cluster];
      glyph.right_to_left = rtl;
      glyph.advance_px = placed[g].x_advance / 64.0;
      pen += glyph.advance_px;
      line.glyphs.push_back(glyph);
    }
  }

 private:
  FontSet& fonts_;
  const std::u32string& shaped_;
  const int size_, script_size_;
  hb_buffer_t* buffer_;
  const hb_language_t language_;
  std::vector<std::uint32_t> cluster_starts_;
};

}  // namespace

ShapedLine shapeLine(FontSet& fonts, std::string_view text, double size_px) {
  ShapedLine line;
  line.text = decodeUtf8(text);
  const std::u32string& chars = line.text;
  if (chars.empty()) return line;
  const int size = std::max(1, static_cast<int>(std::lround(size_px)));
  const int script_size = std::max(1, static_cast<int>(std::lround(kScriptScale * size)));
  const ShapingInput in = shapingInput(fonts, chars);
  const std::vector<FriBidiLevel> levels = embeddingLevels(chars, fonts.rightToLeft());
  const std::vector<Run> runs = runsOf(in, levels);
  RunShaper shaper(fonts, in.shaped, size, script_size);
  double pen = 0.0;
  for (const std::size_t k : visualOrder(runs)) shaper.shape(runs[k], pen, line);
  line.width_px = pen;
  return line;
}

}  // namespace collide::render
