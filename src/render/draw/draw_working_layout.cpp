// SPDX-License-Identifier: MIT
#include "render/draw/draw_working_layout.hpp"

#include <algorithm>
#include <cmath>

#include "frame/layout.hpp"

namespace collide::render {
namespace {

constexpr double kLeadingEm = 0.2;   // between lines of math
constexpr double kFlowGapEm = 1.2;   // between given values in a row
constexpr double kContinueEm = 1.0;  // a side's continuation, indented past its equals sign
constexpr double kSqueezeMargin = 0.97;
constexpr double kShortShare = 0.3;

// The working's own whole numbers, written in ASCII (the 2 of a square, the 1 and 2 of ½, the 1
// of 1 + e), in the frame's digits, as the formatted numbers beside them are: Arabic-Indic in
// Arabic. Subscripts stay: they name bodies (m₁), as the scene's labels write them.
text::Math withFrameDigits(text::Math math, const text::NumberStyle& numbers) {
  if (math.kind == text::MathKind::kNumber) {
    math.text = text::withLocalDigits(math.text, numbers);
    return math;
  }
  for (std::size_t k = 0; k < math.parts.size(); ++k) {
    const bool subscript = math.kind == text::MathKind::kScripts && k == 1;
    if (!subscript) math.parts[k] = withFrameDigits(std::move(math.parts[k]), numbers);
  }
  return math;
}

bool breaksBefore(const text::Math& part) {
  return part.kind == text::MathKind::kOperator &&
         (part.text == "+" || part.text == "−" || part.text == "·" || part.text == "×");
}

// The parts of a side side by side, rows within rows opened (a sum of sums); fences and
// fractions stay whole.
void flatten(const text::Math& math, std::vector<text::Math>& parts) {
  if (math.kind != text::MathKind::kRow) {
    parts.push_back(math);
    return;
  }
  for (const text::Math& part : math.parts) flatten(part, parts);
}

// "= side" as its pieces, each starting with its operator: "= a", "+ b", "· c". An empty row
// first spaces each piece's operator as the whole row would (the typesetter spaces a binary
// operator only after something).
std::vector<MathBox> sidePieces(const text::Math& side, FontSet& fonts, double size_px,
                                const std::vector<double>& scales, std::size_t& index) {
  std::vector<text::Math> parts;
  flatten(side, parts);
  std::vector<text::Math> pieces{text::row({text::row({}), text::op("=")})};
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const bool new_piece = k > 0 && breaksBefore(parts[k]) && !pieces.back().parts.empty();
    if (new_piece) pieces.push_back(text::row({text::row({})}));
    pieces.back().parts.push_back(parts[k]);
  }
  std::vector<MathBox> boxes;
  for (const text::Math& piece : pieces) {
    const double scale = index < scales.size() ? scales[index] : 1.0;
    boxes.push_back(typesetMath(fonts, piece, size_px * scale));
    ++index;
  }
  return boxes;
}

}  // namespace

std::vector<SetLine> setWorkingLines(const frame::WorkingModel& working,
                                     const text::NumberStyle& numbers, FontSet& fonts,
                                     double size_px, const PieceScales& piece_scales) {
  std::vector<SetLine> lines;
  int step = -1;
  for (std::size_t k = 0; k < working.lines.size(); ++k) {
    const frame::WorkingLine& line = working.lines[k];
    SetLine set;
    set.source = k;
    set.part = line.part;
    if (line.sides.empty()) {
      ++step;
      set.heading = line.heading;
    } else {
      std::vector<text::Math> sides = line.sides;
      if (!numbers.digits.empty()) {
        for (text::Math& side : sides) side = withFrameDigits(std::move(side), numbers);
      }
      set.left = typesetMath(fonts, sides[0], size_px);
      static const std::vector<double> kNone;
      const std::vector<double>& scales = k < piece_scales.size() ? piece_scales[k] : kNone;
      std::size_t index = 0;
      for (std::size_t s = 1; s < sides.size(); ++s) {
        set.sides.push_back(sidePieces(sides[s], fonts, size_px, scales, index));
      }
    }
    set.step = std::max(0, step);
    lines.push_back(std::move(set));
  }
  return lines;
}

namespace {

bool leftOut(const SetLine& line, const PlanOptions& o) {
  return (o.skip_repeats && line.part == frame::WorkingPart::kRepeatedResult) ||
         (o.skip_given && line.part == frame::WorkingPart::kGiven && line.heading.empty());
}

// Builds the plan line by line: pieces wait in `row` until the line is finished, its baseline
// then set by its tallest piece.
class Planner {
 public:
  Planner(const std::vector<SetLine>& lines, const PlanOptions& o) : lines_(lines), o_(o) {
    size_ = o.size_px * o.scale;
    plan_.piece_scales.resize(lines.size());
    findFlowing();
    for (const SetLine& line : lines) {
      if (static_cast<std::size_t>(line.step) >= equals_x_.size()) {
        equals_x_.resize(line.step + 1, 0.0);
        has_lines_.resize(line.step + 1, false);
      }
      if (line.heading.empty() && !leftOut(line, o)) {
        has_lines_[line.step] = true;
        if (!flows_[line.source]) {
          equals_x_[line.step] = std::max(equals_x_[line.step], w(line.left));
        }
      }
    }
  }

  WorkingPlan plan() {
    for (const SetLine& line : lines_) {
      if (!line.heading.empty()) {
        heading(line);
      } else if (leftOut(line, o_)) {
        continue;
      } else if (flows_[line.source]) {
        flowing(line);
      } else {
        equation(line);
      }
    }
    finishLine();
    plan_.height_px = y_;
    return std::move(plan_);
  }

 private:
  double w(const MathBox& box) const { return o_.scale * box.width_px; }
  double sideWidth(const std::vector<MathBox>& pieces) const {
    double total = 0.0;
    for (const MathBox& piece : pieces) total += w(piece);
    return total;
  }

  void heading(const SetLine& line) {
    finishLine();
    const double line_px = std::round(frame::kLineSpacing * o_.heading_px);
    if (o_.skip_given && line.part == frame::WorkingPart::kGiven) {
      for (const std::string& text : o_.note) {
        plan_.words.push_back({line.source, text, y_, true});
        y_ += line_px;
      }
      return;
    }
    if (!has_lines_[line.step]) return;  // its lines all left out
    plan_.words.push_back({line.source, line.heading, y_, false});
    y_ += line_px;
  }

  // Short equations stand several to a row, as the given values do: two or more in a row of a
  // step, each "a = b" narrower than kShortShare of the room (v₁ₙ = 1.30 m/s, v₁ₜ = 0.750 m/s).
  bool shortEquation(const SetLine& line) const {
    if (!line.heading.empty() || line.sides.size() != 1 || leftOut(line, o_)) return false;
    return w(line.left) + sideWidth(line.sides[0]) <= kShortShare * o_.width_px;
  }

  void findFlowing() {
    flows_.assign(lines_.size(), false);
    for (std::size_t k = 0; k < lines_.size(); ++k) {
      const SetLine& line = lines_[k];
      if (line.part == frame::WorkingPart::kGiven && line.heading.empty()) flows_[k] = true;
      if (!shortEquation(line)) continue;
      const bool before = k > 0 && lines_[k - 1].step == line.step && shortEquation(lines_[k - 1]);
      const bool after =
          k + 1 < lines_.size() && lines_[k + 1].step == line.step && shortEquation(lines_[k + 1]);
      if (before || after) flows_[k] = true;
    }
  }

  // An equation beside the one before where the row has room.
  void flowing(const SetLine& line) {
    double width = w(line.left);
    for (const auto& side : line.sides) width += sideWidth(side);
    if (!row_.empty() && x_ + kFlowGapEm * size_ + width > o_.width_px) finishLine();
    if (!row_.empty()) x_ += kFlowGapEm * size_;
    put(line.source, line.left, x_);
    for (const auto& side : line.sides) {
      for (const MathBox& piece : side) put(line.source, piece, x_);
    }
    if (x_ > o_.width_px + 0.5) plan_.overflows = true;
  }

  // The share of its size a piece is set at: what lets it fit a line of its own.
  double squeezeOf(const MathBox& piece, bool continues, double equals_x) {
    if (!o_.squeeze) return 1.0;
    const double room = o_.width_px - equals_x - (continues ? kContinueEm * size_ : 0.0);
    // A little short of the room: a piece set smaller is not exactly that much narrower.
    const double squeeze = std::min(1.0, kSqueezeMargin * room / std::max(1.0, w(piece)));
    if (squeeze < kLeastSqueeze) plan_.overflows = true;
    return std::max(kLeastSqueeze, squeeze);
  }

  void equation(const SetLine& line) {
    finishLine();
    const double equals_x = equals_x_[line.step];
    x_ = equals_x - w(line.left);
    put(line.source, line.left, x_, 1.0);
    for (const std::vector<MathBox>& side : line.sides) {
      std::vector<double> scales;
      double width = 0.0;
      for (std::size_t k = 0; k < side.size(); ++k) {
        scales.push_back(squeezeOf(side[k], k > 0, equals_x));
        width += scales.back() * w(side[k]);
      }
      // A side where there is room for it, else on the next line under the equals signs.
      if (x_ > equals_x && x_ + width > o_.width_px) {
        finishLine();
        x_ = equals_x;
      }
      for (std::size_t k = 0; k < side.size(); ++k) {
        if (k > 0 && x_ + scales[k] * w(side[k]) > o_.width_px) {
          finishLine();
          x_ = equals_x + kContinueEm * size_;
        }
        put(line.source, side[k], x_, scales[k]);
        if (o_.squeeze) plan_.piece_scales[line.source].push_back(scales[k]);
      }
      if (x_ > o_.width_px + 0.5) plan_.overflows = true;
    }
    finishLine();
  }

  void put(std::size_t source, const MathBox& box, double& x, double squeeze = 1.0) {
    row_.push_back({source, &box, x, 0.0, squeeze * o_.scale});
    x += squeeze * w(box);
  }

  void finishLine() {
    if (row_.empty()) return;
    double ascent = 0.0, descent = 0.0;
    for (const PlacedMath& placed : row_) {
      ascent = std::max(ascent, placed.scale * placed.box->ascent_px);
      descent = std::max(descent, placed.scale * placed.box->descent_px);
    }
    const double baseline = std::round(y_ + ascent + 0.5 * kLeadingEm * size_);
    for (PlacedMath& placed : row_) {
      placed.baseline_px = baseline;
      plan_.math.push_back(placed);
    }
    y_ += ascent + descent + kLeadingEm * size_;
    row_.clear();
    x_ = 0.0;
  }

  const std::vector<SetLine>& lines_;
  const PlanOptions& o_;
  double size_ = 0.0;
  std::vector<double> equals_x_;
  std::vector<bool> has_lines_;
  std::vector<bool> flows_;  // per line: set beside the line before
  std::vector<PlacedMath> row_;
  double x_ = 0.0, y_ = 0.0;
  WorkingPlan plan_;
};

}  // namespace

WorkingPlan planWorking(const std::vector<SetLine>& lines, const PlanOptions& options) {
  return Planner(lines, options).plan();
}

}  // namespace collide::render
