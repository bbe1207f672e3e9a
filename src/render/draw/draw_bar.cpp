// SPDX-License-Identifier: MIT
#include "render/draw/draw_bar.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "frame/mark_sizes.hpp"
#include "render/draw/bar_leaders.hpp"
#include "render/draw/frame_drawing.hpp"

namespace collide::render {
namespace {

// Between the bar's entries in flowing rows, em: as frame::barLabelRows counts the rows.
constexpr double kBarFlowGapEm = 0.5;
// The legend entry of one bar segment: the width of the room it keeps (swatch, pad and its
// widest text, frame::barLabelRoom) and where it stands: the left end of its box and its row.
struct BarLabel {
  std::size_t segment;
  double width;
  double x0 = 0.0;
  int row = 0;
};

// The middle of each entry's slot across the row.
std::vector<double> slotMiddles(const std::vector<BarLabel>& labels, const frame::EnergyBar& bar,
                                const frame::PixelRect& row_box) {
  const double slot = row_box.width() / static_cast<double>(frame::barLabelSlots(bar));
  std::vector<double> middles;
  for (const BarLabel& label : labels) {
    middles.push_back(row_box.x0 +
                      (static_cast<double>(frame::barLabelSlot(bar, label.segment)) + 0.5) * slot);
  }
  return middles;
}

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

// A crowded bar's entries, in staggered rows, each as near its slot's middle as the others leave
// room for: where its segment is would move it with every change of the energies (the leader
// follows the segment instead).
void placeFlowing(std::vector<BarLabel>& labels, const std::vector<double>& middles, int rows,
                  double gap, const frame::PixelRect& row_box) {
  for (int row = 0; row < rows; ++row) {
    std::vector<double> wanted, widths;
    std::vector<std::size_t> members;
    for (std::size_t k = static_cast<std::size_t>(row); k < labels.size(); k += rows) {
      wanted.push_back(middles[k]);
      widths.push_back(labels[k].width);
      members.push_back(k);
    }
    const std::vector<double> x0s =
        frame::spreadIntervals(wanted, widths, gap, row_box.x0, row_box.x1);
    for (std::size_t m = 0; m < members.size(); ++m) {
      labels[members[m]].x0 = x0s[m];
      labels[members[m]].row = row;
    }
  }
}

// The segments' labels, each a colour swatch and its text (so colour is never the only cue),
// joined to the middle of its segment by a leader. Every entry with a room keeps it (placed as
// though labelled), so the rows and places stay the same through a video; only those labelled
// now are drawn.
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
  const std::size_t slots = frame::barLabelSlots(bar);
  // As many staggered rows as the layout made room for (layoutFrame), more only if it did not
  // measure them.
  const int rows =
      std::max(where.bar_label_rows, frame::barLabelRows(widths, slots, size, row_box.width()));
  if (frame::barLabelsInSlots(widths, slots, size, row_box.width())) {
    placeInSlots(labels, bar, row_box, style.right_to_left);
  } else {
    placeFlowing(labels, slotMiddles(labels, bar, row_box), rows, kBarFlowGapEm * size, row_box);
  }
  const double line = std::round(1.3 * size);
  const double tick_bottom = where.bar_labels.y0 + (where.bar_labels.height() - rows * line);
  const double leader = std::max(1.0, 0.4 * layout.line_px);
  // Each drawn entry's box, its leader's start and its swatch, then where each leader ends.
  std::vector<const BarLabel*> drawn;
  std::vector<BarLeaderEntry> entries;
  for (const BarLabel& label : labels) {
    const frame::EnergySegment& segment = bar.segments[label.segment];
    if (segment.label.empty()) continue;
    const double mid_y = tick_bottom + label.row * line + 0.5 * line;
    const double swatch_x0 = style.right_to_left ? label.x0 + label.width - swatch : label.x0;
    const double text_w = canvas.painter().width(segment.label, size);
    const double x0 = style.right_to_left ? swatch_x0 + swatch - (swatch + pad + text_w) : label.x0;
    drawn.push_back(&label);
    // The text's own height (its ascender and descender, about 1.2 em), not its line's.
    entries.push_back({{x0, mid_y - 0.6 * size, x0 + swatch + pad + text_w, mid_y + 0.6 * size},
                       {middles[label.segment], where.bar_outer.y1 + 0.5 * leader},
                       {swatch_x0 + 0.5 * swatch, mid_y - 0.5 * swatch}});
  }
  const std::vector<core::Vec2> ends = barLeaderEnds(entries, 0.5 * leader);
  for (std::size_t k = 0; k < drawn.size(); ++k) {
    const BarLabel& label = *drawn[k];
    const frame::EnergySegment& segment = bar.segments[label.segment];
    const std::string id = "energy." + std::to_string(label.segment + 1);
    const double mid_y = tick_bottom + label.row * line + 0.5 * line;
    // The swatch where the label starts to be read: left of the text, or right of it in a
    // language read from the right; the text beside it (its room may be wider).
    const double swatch_x0 = style.right_to_left ? label.x0 + label.width - swatch : label.x0;
    const double text_x = style.right_to_left ? swatch_x0 - pad : label.x0 + swatch + pad;
    {
      // The leader follows its segment while the label may stand still: an item of its own.
      const DrawnItemScope leader_item(mesh, "leader." + id, "leader");
      mesh.addLine(entries[k].from_px, ends[k], leader, style.muted_text);
    }
    const DrawnItemScope label_item(mesh, id, "readout");
    const frame::PixelRect box{swatch_x0, mid_y - 0.5 * swatch, swatch_x0 + swatch,
                               mid_y + 0.5 * swatch};
    mesh.addRect(box, segment.color);
    mesh.addRectFrame(box, std::max(1.0, 0.08 * size), style.muted_text);
    canvas.text(segment.label, {text_x, mid_y}, size, style.text,
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
