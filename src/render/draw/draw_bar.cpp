// SPDX-License-Identifier: MIT
#include "render/draw/draw_bar.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "frame/bar_legend.hpp"
#include "frame/mark_sizes.hpp"
#include "render/draw/bar_leaders.hpp"
#include "render/draw/frame_drawing.hpp"

namespace collide::render {
namespace {

// The legend entry of one bar segment: the width of the room it keeps (swatch, pad and its
// widest text, frame::barLabelRoom) and where it stands: the left end of its box, its row and,
// in a staircase, its column (where its leader comes down onto it).
struct BarLabel {
  std::size_t segment;
  double width;
  double x0 = 0.0;
  int row = 0;
  std::optional<double> column = std::nullopt;
};

// Fixed slots, one per segment that has one, across the bar in one row
// (frame::barLabelsInSlots): a label keeps its place while its segment grows and shrinks, and a
// label that appears or goes leaves the others where they stand. Each stands at its slot's
// reading start: its left end, or its right end in a language read from the right.
void placeInSlots(std::vector<BarLabel>& labels, const frame::EnergyBar& bar,
                  const frame::PixelRect& row_box, bool right_to_left) {
  const double slot = row_box.width() / static_cast<double>(frame::barLabelSlots(bar));
  for (BarLabel& label : labels) {
    const double slot_x0 =
        row_box.x0 + static_cast<double>(frame::barLabelSlot(bar, label.segment)) * slot;
    label.x0 = right_to_left ? std::max(row_box.x0, slot_x0 + slot - label.width)
                             : std::min(slot_x0, row_box.x1 - label.width);
  }
}

// A crowded bar's entries as a staircase in the segments' order (frame::barStaircase), planned
// in reading order: mirrored in a language read from the right, whose swatches stand at the
// entries' right ends. Returns its rows.
int placeInStaircase(std::vector<BarLabel>& labels, double size, double swatch,
                     const frame::PixelRect& row_box, bool right_to_left) {
  std::vector<double> widths;
  for (const BarLabel& label : labels) widths.push_back(label.width);
  if (right_to_left) std::reverse(widths.begin(), widths.end());
  const frame::BarStaircase stairs =
      frame::barStaircase(widths, size, swatch, row_box.x0, row_box.x1);
  const std::size_t n = labels.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t r = right_to_left ? n - 1 - k : k;
    BarLabel& label = labels[k];
    label.row = stairs.row[r];
    label.x0 =
        right_to_left ? row_box.x0 + row_box.x1 - stairs.x0_px[r] - label.width : stairs.x0_px[r];
    label.column =
        right_to_left ? row_box.x0 + row_box.x1 - stairs.column_px[r] : stairs.column_px[r];
  }
  return stairs.rows;
}

// Where the leaders start, for the entries in their order: under their segments' middles, in
// that order and at least `apart_px` apart (a tiny segment's leader beside its neighbour's, a
// strip's to the right of the part it lies on), within `inner`.
std::vector<double> leaderStarts(std::vector<double> middles, double apart_px,
                                 const frame::PixelRect& inner) {
  for (std::size_t k = 1; k < middles.size(); ++k) {
    middles[k] = std::max(middles[k], middles[k - 1] + apart_px);
  }
  for (std::size_t k = middles.size(); k-- > 0;) {
    const double most = k + 1 < middles.size() ? middles[k + 1] - apart_px : inner.x1;
    middles[k] = std::max(inner.x0, std::min(middles[k], most));
  }
  return middles;
}

// Where the drawn entries' leaders start, as points: along the bar's lower edge (bottom_y) at
// xs (leaderStarts), but where a strip (frame::EnergySegment::strip, the energy released) runs
// along that edge, a part's leader starts above the strip, on the part it names, so that it does
// not read as the strip's; and a strip's own leader starts on the strip as near above its swatch
// (swatch_xs) as it may while a line of text (keep_px) from its neighbours' starts, so that
// neither seems to continue the other (else midway between them).
struct LeaderStartRule {
  double apart_px;  // leaderStarts' least distance between two starts
  double keep_px;   // a strip's start from its neighbours', where the strip leaves room
  double bottom_y;  // the bar's lower edge, where leaders start
  double rule_px;   // the background line above a strip
};
std::vector<core::Vec2> leaderPoints(std::vector<double> xs, const std::vector<double>& swatch_xs,
                                     const std::vector<std::optional<frame::PixelRect>>& strips,
                                     const LeaderStartRule& rule, const frame::PixelRect& inner) {
  std::vector<core::Vec2> points;
  for (std::size_t k = 0; k < xs.size(); ++k) {
    if (strips[k]) {
      const auto span = [&](double margin_px) {
        return std::pair{
            std::max(strips[k]->x0, k > 0 ? xs[k - 1] + margin_px : inner.x0),
            std::min(strips[k]->x1, k + 1 < xs.size() ? xs[k + 1] - margin_px : inner.x1)};
      };
      if (const auto [lo, hi] = span(rule.keep_px); lo <= hi) {
        xs[k] = std::clamp(swatch_xs[k], lo, hi);
      } else if (const auto [near_lo, near_hi] = span(rule.apart_px); near_lo <= near_hi) {
        xs[k] = 0.5 * (near_lo + near_hi);
      }
      points.push_back({xs[k], rule.bottom_y});
      continue;
    }
    double from_y = rule.bottom_y;
    for (const std::optional<frame::PixelRect>& strip : strips) {
      if (strip && xs[k] >= strip->x0 && xs[k] <= strip->x1) {
        from_y = std::min(from_y, strip->y0 - rule.rule_px);
      }
    }
    points.push_back({xs[k], from_y});
  }
  return points;
}

// One drawn entry: its label, the middle of its line and its leader's points.
struct DrawnEntry {
  const BarLabel* label;
  double mid_y;
  std::vector<core::Vec2> leader;
};

// Each drawn entry's leader: in slots, straight from under its segment to where it strikes
// through no other entry (barLeaderEnds); in a staircase, from under its segment slanting to
// its column just above the first row, then straight down onto its swatch (or its box's top).
void routeLeaders(std::vector<DrawnEntry>& drawn, const std::vector<core::Vec2>& starts,
                  const frame::EnergyBar& bar, const frame::FrameStyle& style, double size,
                  double swatch, double pad, double band_y, double clear, TextPainter& painter) {
  std::vector<BarLeaderEntry> entries;
  for (std::size_t k = 0; k < drawn.size(); ++k) {
    const BarLabel& label = *drawn[k].label;
    const double mid_y = drawn[k].mid_y;
    const double swatch_x0 = style.right_to_left ? label.x0 + label.width - swatch : label.x0;
    const core::Vec2& from = starts[k];
    if (label.column) {
      const double column = *label.column;
      const bool on_swatch = std::abs(column - (swatch_x0 + 0.5 * swatch)) < 0.5;
      const double land_y = on_swatch ? mid_y - 0.5 * swatch : mid_y - 0.6 * size;
      drawn[k].leader = {from, {column, band_y}, {column, land_y}};
      continue;
    }
    const double text_w = painter.width(bar.segments[label.segment].label, size);
    const double x0 = style.right_to_left ? swatch_x0 + swatch - (swatch + pad + text_w) : label.x0;
    // The text's own height (its ascender and descender, about 1.2 em), not its line's.
    entries.push_back({{x0, mid_y - 0.6 * size, x0 + swatch + pad + text_w, mid_y + 0.6 * size},
                       from,
                       {swatch_x0 + 0.5 * swatch, mid_y - 0.5 * swatch}});
  }
  if (entries.empty()) return;
  const std::vector<core::Vec2> ends = barLeaderEnds(entries, clear);
  for (std::size_t k = 0; k < drawn.size(); ++k) drawn[k].leader = {entries[k].from_px, ends[k]};
}

// The segments' labels, each a colour swatch and its text (so colour is never the only cue),
// joined to its segment by a leader. Every entry with a room keeps it (placed as though
// labelled), so the rows and places stay the same through a video; only those labelled now are
// drawn.
void drawBarLabels(const frame::EnergyBar& bar, const frame::FrameStyle& style,
                   const frame::PanelLayout& where, const frame::FrameLayout& layout,
                   Canvas& canvas, const std::vector<double>& middles) {
  ShapeSink& mesh = canvas.shapes();
  const double size = layout.small_px, swatch = frame::kBarSwatchEm * size,
               pad = frame::kBarPadEm * size;
  std::vector<BarLabel> labels;
  std::vector<double> widths;
  for (std::size_t i = 0; i < bar.segments.size(); ++i) {
    // A segment without a slot is never labelled (compose: the loss of a run that loses nothing).
    const std::string& room = frame::barLabelRoom(bar.segments[i]);
    if (room.empty() || !bar.segments[i].has_slot) continue;
    const double w = swatch + pad + canvas.painter().width(room, size);
    labels.push_back({i, w});
    widths.push_back(w);
  }
  if (labels.empty()) return;
  const frame::PixelRect& row_box = where.bar_outer;
  int rows = 1;
  if (frame::barLabelsInSlots(widths, frame::barLabelSlots(bar), size, row_box.width())) {
    placeInSlots(labels, bar, row_box, style.right_to_left);
  } else {
    rows = placeInStaircase(labels, size, swatch, row_box, style.right_to_left);
  }
  // As many rows as the layout made room for (layoutFrame), more only if it did not measure them.
  rows = std::max(rows, where.bar_label_rows);
  const double line = std::round(1.3 * size);
  const double tick_bottom = where.bar_labels.y0 + (where.bar_labels.height() - rows * line);
  const double leader = std::max(1.0, 0.4 * layout.line_px);
  std::vector<DrawnEntry> drawn;
  std::vector<double> drawn_middles, swatch_xs;
  std::vector<std::optional<frame::PixelRect>> strips;
  for (const BarLabel& label : labels) {
    const frame::EnergySegment& segment = bar.segments[label.segment];
    if (segment.label.empty()) continue;
    drawn.push_back({&label, tick_bottom + label.row * line + 0.5 * line, {}});
    drawn_middles.push_back(middles[label.segment]);
    swatch_xs.push_back(style.right_to_left ? label.x0 + label.width - 0.5 * swatch
                                            : label.x0 + 0.5 * swatch);
    strips.push_back(segment.strip ? std::optional{frame::barStripPx(bar, segment, where.bar_inner)}
                                   : std::nullopt);
  }
  const LeaderStartRule rule{std::max(2.0, 2.0 * leader), frame::kLineSpacing * layout.text_px,
                             where.bar_outer.y1 + 0.5 * leader, std::max(1.0, layout.bar_frame_px)};
  routeLeaders(drawn,
               leaderPoints(leaderStarts(drawn_middles, rule.apart_px, where.bar_inner), swatch_xs,
                            strips, rule, where.bar_inner),
               bar, style, size, swatch, pad, tick_bottom, 0.5 * leader, canvas.painter());
  for (const DrawnEntry& entry : drawn) {
    const BarLabel& label = *entry.label;
    const frame::EnergySegment& segment = bar.segments[label.segment];
    const std::string id = "energy." + std::to_string(label.segment + 1);
    // The swatch where the label starts to be read: left of the text, or right of it in a
    // language read from the right; the text beside it (its room may be wider).
    const double swatch_x0 = style.right_to_left ? label.x0 + label.width - swatch : label.x0;
    const double text_x = style.right_to_left ? swatch_x0 - pad : label.x0 + swatch + pad;
    {
      // The leader follows its segment while the label may stand still: an item of its own.
      const DrawnItemScope leader_item(mesh, "leader." + id, "leader");
      if (entry.leader.size() == 2) {
        mesh.addLine(entry.leader[0], entry.leader[1], leader, style.muted_text);
      } else {
        mesh.addPolyline(entry.leader, leader, style.muted_text);
      }
      mesh.describePath(entry.leader);
    }
    const DrawnItemScope label_item(mesh, id, "readout");
    const frame::PixelRect box{swatch_x0, entry.mid_y - 0.5 * swatch, swatch_x0 + swatch,
                               entry.mid_y + 0.5 * swatch};
    mesh.addRect(box, segment.color);
    mesh.addRectFrame(box, std::max(1.0, 0.08 * size), style.muted_text);
    canvas.text(segment.label, {text_x, entry.mid_y}, size, style.text,
                style.right_to_left ? HAlign::kRight : HAlign::kLeft, VAlign::kMiddle);
  }
}

// The parts, left to right between their edges.
void drawBarParts(const frame::EnergyBar& bar, const std::vector<double>& edges,
                  const frame::PanelLayout& where, ShapeSink& mesh) {
  for (std::size_t i = 0; i < bar.segments.size(); ++i) {
    if (bar.segments[i].strip) continue;  // drawn over the parts: drawBarStrips
    // An opaque segment followed by an opaque one reaches a pixel under it (with the GL painter),
    // so the boundary pixel mixes the two colours instead of letting the background through;
    // never out to the last edge of the opaque run, whose pixel must mix with the background
    // alone.
    std::size_t run_end = i + 1;
    while (run_end < bar.segments.size() && bar.segments[run_end - 1].color.a >= 1.0f &&
           bar.segments[run_end].color.a >= 1.0f) {
      ++run_end;
    }
    const double cover = mesh.seamCoverPx();
    const double reach =
        std::max(edges[i + 1], std::min(edges[i + 1] + cover, edges[run_end] - cover));
    mesh.addRect({edges[i], where.bar_inner.y0, reach, where.bar_inner.y1}, bar.segments[i].color);
  }
}

// The strips over the parts (frame::EnergySegment::strip), each with a line of the background
// above it that sets it apart from the parts it lies on.
void drawBarStrips(const frame::EnergyBar& bar, const frame::FrameStyle& style,
                   const frame::PanelLayout& where, const frame::FrameLayout& layout,
                   ShapeSink& mesh) {
  for (const frame::EnergySegment& segment : bar.segments) {
    if (!segment.strip) continue;
    const frame::PixelRect strip = frame::barStripPx(bar, segment, where.bar_inner);
    if (!(strip.width() > 0.0)) continue;
    const double rule = std::max(1.0, layout.bar_frame_px);
    mesh.addRect({strip.x0, strip.y0 - rule, strip.x1, strip.y0}, style.background);
    mesh.addRect(strip, segment.color);
  }
}

}  // namespace

void drawBar(const frame::EnergyBar& bar, const frame::FrameStyle& style,
             const frame::PanelLayout& where, const frame::FrameLayout& layout, Canvas& canvas) {
  ShapeSink& mesh = canvas.shapes();
  std::optional<DrawnItemScope> item(std::in_place, mesh, "energy_bar", "bar");
  mesh.addRectFrame(where.bar_outer, layout.bar_frame_px, style.bar_frame);
  if (bar.full_scale_J <= 0.0) return;
  const std::vector<double> edges = frame::barSegmentEdgesPx(bar, where.bar_inner);
  drawBarParts(bar, edges, where, mesh);
  drawBarStrips(bar, style, where, layout, mesh);
  // Where each segment's leader starts: a part's middle, a strip's own.
  std::vector<double> middles;
  for (std::size_t i = 0; i < bar.segments.size(); ++i) {
    const frame::PixelRect strip = frame::barStripPx(bar, bar.segments[i], where.bar_inner);
    middles.push_back(bar.segments[i].strip ? 0.5 * (strip.x0 + strip.x1)
                                            : 0.5 * (edges[i] + edges[i + 1]));
  }
  item.reset();
  drawBarLabels(bar, style, where, layout, canvas, middles);
}

}  // namespace collide::render
