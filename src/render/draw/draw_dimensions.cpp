// SPDX-License-Identifier: MIT
// Dimension lines (a ballistic pendulum's rise, a skid's length) with their labels and notes.
#include <optional>
#include <string>
#include <vector>

#include "frame/mark_sizes.hpp"
#include "render/draw/frame_drawing.hpp"

namespace collide::render {
namespace {

// An arrowhead with its tip at `tip`, pointing along the unit vector `along`.
void addHead(ShapeSink& mesh, const core::Vec2& tip, const core::Vec2& along, double head_px,
             const frame::Rgba& color) {
  const core::Vec2 base = tip - head_px * along;
  const core::Vec2 side = 0.35 * head_px * core::Vec2{-along.y(), along.x()};
  mesh.addTriangle(tip, base + side, base - side, color);
}

// The lines and the arrowheads: inside the tips pointing out at the extension lines, or, on a
// length too short for that, outside them pointing in.
void drawLines(const frame::DimensionGeometry& g, const frame::FrameStyle& style, ShapeSink& mesh) {
  for (int k : {0, 1}) mesh.addLine(g.lines[k].a, g.lines[k].b, g.thin_px, style.muted_text);
  const core::Vec2 span = g.to_tip_px - g.from_tip_px;
  const double length = span.norm();
  const core::Vec2 along = length > 0.0
                               ? core::Vec2(span / length)
                               : core::Vec2(g.horizontal ? 1.0 : 0.0, g.horizontal ? 0.0 : -1.0);
  const double head = g.head_px;
  if (g.heads_outside) {
    mesh.addLine(g.lines[2].a, g.lines[2].b, g.thin_px, style.text);
    addHead(mesh, g.to_tip_px, -along, head, style.text);
    addHead(mesh, g.from_tip_px, along, head, style.text);
    return;
  }
  // The line stops short of the tips, under the heads, so they end sharp.
  mesh.addLine(g.from_tip_px + head * along, g.to_tip_px - head * along, g.thin_px, style.text);
  addHead(mesh, g.to_tip_px, along, head, style.text);
  addHead(mesh, g.from_tip_px, -along, head, style.text);
}

// The label where the painter puts it on its own: a vertical line's right of its middle (left
// where the frame ends first), a horizontal line's centred above it.
void drawOwnLabel(const frame::DimensionModel& dim, const frame::DimensionGeometry& g,
                  const frame::FrameStyle& style, const frame::FrameLayout& layout,
                  Canvas& canvas) {
  const double head = g.head_px;
  const core::Vec2 middle = 0.5 * (g.from_tip_px + g.to_tip_px);
  if (g.horizontal) {
    canvas.text(dim.label, {middle.x(), middle.y() - 0.5 * head}, layout.text_px, style.text,
                HAlign::kCenter, VAlign::kBottom);
    return;
  }
  const double wide = canvas.painter().width(dim.label, layout.text_px);
  const double x = middle.x();
  const bool right = x + 0.6 * head + wide <= layout.width_px - 0.5 * head;
  const core::Vec2 at{right ? x + 0.6 * head : x - 0.6 * head, middle.y()};
  canvas.text(dim.label, at, layout.text_px, style.text, right ? HAlign::kLeft : HAlign::kRight,
              VAlign::kMiddle);
}

void drawNotes(const frame::DimensionModel& dim, const std::string& id,
               const frame::FrameStyle& style, const frame::FrameLayout& layout,
               const frame::WorldToPixel& to_px, bool placed, Canvas& canvas) {
  if (dim.notes.empty() || (placed && !dim.notes_at_px)) return;  // none, or no free place
  const DrawnItemScope notes(canvas.shapes(), id + ".notes", "caption");
  core::Vec2 note_at = placed ? *dim.notes_at_px : to_px.toPixel(dim.notes_m);
  const std::vector<std::string>& lines =
      placed && !dim.notes_lines.empty() ? dim.notes_lines : dim.notes;
  const double notes_px = placed && dim.notes_px > 0.0 ? dim.notes_px : layout.text_px;
  for (const std::string& line : lines) {
    canvas.text(line, note_at, notes_px, style.text, HAlign::kLeft, VAlign::kTop);
    note_at.y() += 1.3 * notes_px;
  }
}

}  // namespace

void drawDimensions(const std::vector<frame::DimensionModel>& dimensions,
                    const frame::FrameStyle& style, const frame::FrameLayout& layout,
                    const frame::WorldToPixel& to_px, bool placed, Canvas& canvas) {
  ShapeSink& mesh = canvas.shapes();
  for (std::size_t d = 0; d < dimensions.size(); ++d) {
    const frame::DimensionModel& dim = dimensions[d];
    const std::string id = dim.id.empty() ? "dimension." + std::to_string(d + 1) : dim.id;
    std::optional<DrawnItemScope> item(std::in_place, mesh, id, "dimension");
    const frame::DimensionGeometry g = frame::dimensionGeometry(dim, layout, to_px);
    drawLines(g, style, mesh);
    if (!placed) {
      if (!dim.label.empty()) drawOwnLabel(dim, g, style, layout, canvas);
    } else if (dim.label_at && !dim.label.empty()) {
      canvas.text(dim.label, dim.label_at->top_left_px, layout.text_px, style.text, HAlign::kLeft,
                  VAlign::kTop);
    }
    item.reset();
    drawNotes(dim, id, style, layout, to_px, placed, canvas);
  }
}

}  // namespace collide::render
