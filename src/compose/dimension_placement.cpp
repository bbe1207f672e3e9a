#include "compose/dimension_placement.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include "frame/mark_sizes.hpp"
#include "text/text_wrap.hpp"

namespace collide::compose {
namespace {

constexpr double kNoteLineSpacing = 1.3;  // of the text size, as the painter draws the notes
constexpr double kWrapStep = 0.8;         // each narrower wrap of the notes, of the one before
constexpr double kLeastWrapEm = 6.0;      // the narrowest, of the text size: a few words a line

Box boxAt(double x0, double y0, double width, double height) {
  return {x0, y0, x0 + width, y0 + height};
}

// The fan the string of a dimension's body sweeps, in pixels, as a convex polygon: from its
// pivot to the arc between the top of the swing and its mirror image (the body swings back as
// far). The notes stay out of all of it, so they keep one place for the whole swing. Empty where
// no string holds the body (no string is as long as the pivot is from the top of the swing).
std::vector<core::Vec2> swingFan(const frame::DimensionModel& dim,
                                 const frame::SuspensionModel& suspension,
                                 const frame::WorldToPixel& to_px) {
  constexpr int kArcSteps = 12;
  const frame::StringModel* held = nullptr;
  double best = std::numeric_limits<double>::infinity();
  for (const frame::StringModel& string : suspension.strings) {
    const double length = (string.body_m - string.pivot_m).norm();
    const double mismatch = std::abs((dim.to_m - string.pivot_m).norm() - length);
    if (mismatch < best && mismatch <= 1e-3 * std::max(length, 1e-9)) {
      best = mismatch;
      held = &string;
    }
  }
  if (!held) return {};
  const core::Vec2 pivot = held->pivot_m, reach = dim.to_m - pivot;
  const double length = reach.norm();
  const double amplitude =
      std::min(std::abs(std::atan2(reach.x(), -reach.y())), 0.5 * std::numbers::pi);
  std::vector<core::Vec2> fan = {to_px.toPixel(pivot)};
  for (int k = 0; k <= kArcSteps; ++k) {
    const double a = -amplitude + 2.0 * amplitude * k / kArcSteps;
    fan.push_back(to_px.toPixel(pivot + length * core::Vec2{std::sin(a), -std::cos(a)}));
  }
  return fan;
}

// Whether the convex polygon meets the box (separating axes: the box's two and the polygon's
// edge normals).
bool polygonMeets(const std::vector<core::Vec2>& polygon, const Box& box) {
  if (polygon.size() < 3) return false;
  const std::array<core::Vec2, 4> corners = {core::Vec2{box.x0, box.y0}, core::Vec2{box.x1, box.y0},
                                             core::Vec2{box.x1, box.y1},
                                             core::Vec2{box.x0, box.y1}};
  const auto separated = [&](const core::Vec2& axis) {
    double p0 = std::numeric_limits<double>::infinity(), p1 = -p0, b0 = p0, b1 = -p0;
    for (const core::Vec2& p : polygon) {
      p0 = std::min(p0, p.dot(axis));
      p1 = std::max(p1, p.dot(axis));
    }
    for (const core::Vec2& c : corners) {
      b0 = std::min(b0, c.dot(axis));
      b1 = std::max(b1, c.dot(axis));
    }
    return p1 < b0 || b1 < p0;
  };
  if (separated({1.0, 0.0}) || separated({0.0, 1.0})) return false;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const core::Vec2 edge = polygon[(k + 1) % polygon.size()] - polygon[k];
    if (separated({-edge.y(), edge.x()})) return false;
  }
  return true;
}

// The free box of `width` x `height` whose top-left corner is nearest `wanted`, over the clip in
// steps of `step_x` across and `step_y` down; none where no box of that size is free.
template <class Free>
std::optional<Box> nearestFreeBox(const Obstacles& obstacles, const Free& free,
                                  const core::Vec2& wanted, double width, double height,
                                  double step_x, double step_y) {
  const Box& clip = obstacles.clip();
  std::optional<Box> best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (double y = clip.y0; y + height <= clip.y1; y += step_y) {
    for (double x = clip.x0; x + width <= clip.x1; x += step_x) {
      const double d = std::hypot(x - wanted.x(), y - wanted.y());
      if (d >= best_distance) continue;
      const Box box = boxAt(x, y, width, height);
      if (!free(box)) continue;
      best = box;
      best_distance = d;
    }
  }
  return best;
}

// Where a vertical dimension's label (its h) may go, in order: beside the middle of the line,
// right then left; then beside its ends; then further below the lower end, half a line at a
// time (a strobe's image of the swing may stand just under the line): the label still reads as
// the line's, under its foot.
std::vector<Box> verticalLabelPlaces(const frame::DimensionGeometry& g, double w, double line,
                                     double gap) {
  const double x = g.from_tip_px.x(), side = 0.6 * g.head_px;
  const double top = std::min(g.from_px.y(), g.to_px.y());
  const double bottom = std::max(g.from_px.y(), g.to_px.y());
  const double mid = 0.5 * (top + bottom) - 0.5 * line;
  std::vector<Box> candidates = {boxAt(x + side, mid, w, line),
                                 boxAt(x - side - w, mid, w, line),
                                 boxAt(x + side, top - line - gap, w, line),
                                 boxAt(x + side, bottom + gap, w, line),
                                 boxAt(x - side - w, top - line - gap, w, line),
                                 boxAt(x - side - w, bottom + gap, w, line)};
  for (int half_lines = 1; half_lines <= 3; ++half_lines) {
    const double y = bottom + gap + 0.5 * half_lines * line;
    candidates.push_back(boxAt(x - side - w, y, w, line));
  }
  return candidates;
}

// Where a horizontal dimension's label (a skid's d) may go, in order: over the line, then under
// it, centred but never nearer its end than `pad` (a skid's end is its bodies' trailing face: the
// label stays in the free road behind them and moves on smoothly as the line grows); then beside
// the line's start, outside it (a skid just begun is shorter than its label).
std::vector<Box> horizontalLabelPlaces(const frame::DimensionGeometry& g, double pad, double w,
                                       double line, double gap) {
  const double y = g.from_tip_px.y(), side = 0.6 * g.head_px;
  const double start = g.from_tip_px.x(), end = g.to_tip_px.x();
  const double mid = 0.5 * (start + end) - 0.5 * w;
  const bool starts_left = start <= end;
  const double tucked = starts_left ? std::min(mid, end - pad - w) : std::max(mid, end + pad);
  // Outside: past the line as drawn (its heads stand outside a short one).
  const double reach = std::abs(g.lines[2].a.x() - start) + side;
  const double outside = starts_left ? start - reach - w : start + reach;
  return {boxAt(tucked, y - 0.5 * gap - line, w, line), boxAt(tucked, y + 0.5 * gap, w, line),
          boxAt(outside, y - 0.5 * line, w, line)};
}

// The dimension's label: the first free place of its candidates; else, on a screen, the free
// place nearest the line's middle; cleared where it finds no free place.
void placeDimensionLabel(frame::DimensionModel& dim, const frame::DimensionGeometry& g,
                         const frame::FrameLayout& layout, text::TextMeasure& metrics,
                         Obstacles& obstacles) {
  const double size = layout.text_px, gap = layout.gap_px;
  const double line = metrics.ascender(size) + metrics.descender(size);
  const double w = metrics.width(dim.label, size);
  const std::vector<Box> candidates =
      g.horizontal ? horizontalLabelPlaces(g, obstacles.bodyGap() + 1.0, w, line, gap)
                   : verticalLabelPlaces(g, w, line, gap);
  const core::Vec2 middle = 0.5 * (g.from_tip_px + g.to_tip_px);
  const core::Vec2 near = g.horizontal
                              ? core::Vec2{middle.x() - 0.5 * w, middle.y() - line}
                              : core::Vec2{middle.x() + 0.6 * g.head_px, middle.y() - 0.5 * line};
  const auto pick = std::find_if(candidates.begin(), candidates.end(),
                                 [&](const Box& box) { return obstacles.isFree(box); });
  // Else, on a screen, the free place nearest the line's middle; a printed figure whose text
  // the floor enlarged lets it give way (the line still shows h, and the caption says it).
  std::optional<Box> place;
  if (pick != candidates.end()) place = *pick;
  if (!place && layout.scale_px <= layout.height_px) {
    place = nearestFreeBox(
        obstacles, [&](const Box& box) { return obstacles.isFree(box); }, near, w, line,
        std::max(1.0, size), std::max(1.0, 0.5 * line));
  }
  if (!place) {
    dim.label.clear();
    return;
  }
  dim.label_at = frame::PlacedText{{place->x0, place->y0}, {w, line}, std::nullopt};
  obstacles.addText(*place);
}

// The ways to set the notes, in order: each note on one line; else broken after its lead-in
// ("speed from h:", so the formula stays whole); else those pieces wrapped narrower and narrower
// (down to a few words a line).
std::vector<std::vector<std::string>> noteBreakings(const std::vector<std::string>& notes,
                                                    double size, text::TextMeasure& metrics) {
  const text::TextWidth width = [&metrics](std::string_view text, double px) {
    return metrics.width(text, px);
  };
  std::vector<std::vector<std::string>> breakings = {notes, {}};
  double widest = 0.0;
  for (const std::string& note : notes) {
    const std::size_t colon = note.find(": ");
    if (colon == std::string::npos) {
      breakings.back().push_back(note);
    } else {
      breakings.back().push_back(note.substr(0, colon + 1));
      breakings.back().push_back(note.substr(colon + 2));
    }
  }
  const std::vector<std::string> pieces = breakings.back();
  // Never narrower than what must stay on one line ("200 m/s"): a narrower wrap would part a
  // number from its unit, or a unit between its letters ("200 m/" | "s").
  double unbroken = 0.0;
  for (const std::string& piece : pieces) {
    widest = std::max(widest, metrics.width(piece, size));
    unbroken = std::max(unbroken, text::widestUnbrokenPx(piece, size, width));
  }
  const double narrowest = std::max(kLeastWrapEm * size, unbroken);
  for (double wrap = kWrapStep * widest; wrap >= narrowest; wrap *= kWrapStep) {
    std::vector<std::string> lines;
    for (const std::string& piece : pieces) {
      for (std::string& l : text::wrapText(piece, size, wrap, width)) lines.push_back(l);
    }
    breakings.push_back(std::move(lines));
  }
  return breakings;
}

// A place for the notes set in `lines` at `size`: `chosen` or a corner of the clip (pass 0), else
// the free place nearest `chosen` (pass 1), each where `clear` says it is.
template <class Clear>
std::optional<Box> notesPlace(const std::vector<std::string>& lines, double size, int pass,
                              const core::Vec2& chosen, const Clear& clear,
                              const Obstacles& obstacles, const frame::FrameLayout& layout,
                              text::TextMeasure& metrics) {
  const double gap = layout.gap_px;
  const double line = metrics.ascender(size) + metrics.descender(size);
  const Box& clip = obstacles.clip();
  double w = 0.0;
  for (const std::string& l : lines) w = std::max(w, metrics.width(l, size));
  const double h = kNoteLineSpacing * size * static_cast<double>(lines.size() - 1) + line;
  if (pass == 1) {
    return nearestFreeBox(obstacles, clear, chosen, w, h, std::max(1.0, size),
                          std::max(1.0, 0.5 * line));
  }
  for (const Box& box :
       {boxAt(chosen.x(), chosen.y(), w, h), boxAt(clip.x0 + gap, clip.y0 + gap, w, h),
        boxAt(clip.x1 - gap - w, clip.y0 + gap, w, h),
        boxAt(clip.x0 + gap, clip.y1 - gap - h, w, h),
        boxAt(clip.x1 - gap - w, clip.y1 - gap - h, w, h)}) {
    if (clear(box)) return box;
  }
  return std::nullopt;
}

// The notes placed: their lines, their text size and their box.
struct PlacedNotes {
  std::vector<std::string> lines;
  double size_px = 0.0;
  Box box;
};

// The first way to set the notes that finds a place where `clear` says: at the text size, each
// breaking in a corner, then nearest `chosen`; then the same at the small text size (the text
// floor: the notes are the point of the picture, smaller rather than left out).
template <class Clear>
std::optional<PlacedNotes> fitNotes(const frame::DimensionModel& dim, const core::Vec2& chosen,
                                    const Clear& clear, const Obstacles& obstacles,
                                    const frame::FrameLayout& layout, text::TextMeasure& metrics) {
  std::vector<double> sizes = {layout.text_px};
  if (layout.small_px > 0.0 && layout.small_px < layout.text_px) sizes.push_back(layout.small_px);
  for (double size : sizes) {
    const std::vector<std::vector<std::string>> breakings = noteBreakings(dim.notes, size, metrics);
    for (int pass = 0; pass < 2; ++pass) {
      for (const std::vector<std::string>& lines : breakings) {
        const std::optional<Box> box =
            notesPlace(lines, size, pass, chosen, clear, obstacles, layout, metrics);
        if (box) return PlacedNotes{lines, size, *box};
      }
    }
  }
  return std::nullopt;
}

// The dimension's notes: in `notes_m`'s corner or another one, else in the free place nearest to
// it, keeping out of the string's whole swing too, with a gap, so they stay put; else smaller;
// else over the swing (the string may pass behind them: the speed is the picture's point). Only
// a printed figure too small for them at the caption size leaves them unplaced.
void placeDimensionNotes(frame::DimensionModel& dim, const frame::SuspensionModel& suspension,
                         const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
                         text::TextMeasure& metrics, Obstacles& obstacles) {
  const std::vector<core::Vec2> fan = swingFan(dim, suspension, to_px);
  const auto clear = [&](const Box& box) {
    const double pad = obstacles.bodyGap();
    return obstacles.isFree(box) &&
           !polygonMeets(fan, {box.x0 - pad, box.y0 - pad, box.x1 + pad, box.y1 + pad});
  };
  const auto free = [&](const Box& box) { return obstacles.isFree(box); };
  const core::Vec2 chosen = to_px.toPixel(dim.notes_m);
  // A printed figure whose text the floor enlarged (its text sized from more than its height)
  // has no room to spare: its notes take a place at the text size clear of the swing, or none
  // (its caption says them), so that the bodies' labels keep theirs.
  const bool print_enlarged = layout.scale_px > layout.height_px;
  frame::FrameLayout sizes = layout;
  if (print_enlarged) sizes.small_px = layout.text_px;
  std::optional<PlacedNotes> placed = fitNotes(dim, chosen, clear, obstacles, sizes, metrics);
  if (!placed && !print_enlarged) placed = fitNotes(dim, chosen, free, obstacles, layout, metrics);
  if (!placed) return;
  if (placed->lines != dim.notes) dim.notes_lines = placed->lines;
  if (placed->size_px != layout.text_px) dim.notes_px = placed->size_px;
  dim.notes_at_px = core::Vec2{placed->box.x0, placed->box.y0};
  obstacles.addText(placed->box);
}

}  // namespace

void placeDimensionTexts(frame::PanelModel& panel, const frame::FrameLayout& layout,
                         const frame::WorldToPixel& to_px, text::TextMeasure& metrics,
                         Obstacles& obstacles) {
  for (frame::DimensionModel& dim : panel.dimensions) {
    dim.label_at.reset();
    dim.notes_at_px.reset();
    dim.notes_lines.clear();
    dim.notes_px = 0.0;
    const frame::DimensionGeometry g = frame::dimensionGeometry(dim, layout, to_px);
    if (!dim.label.empty()) placeDimensionLabel(dim, g, layout, metrics, obstacles);
    if (dim.notes.empty()) continue;
    placeDimensionNotes(dim, panel.suspension, layout, to_px, metrics, obstacles);
  }
}

}  // namespace collide::compose
