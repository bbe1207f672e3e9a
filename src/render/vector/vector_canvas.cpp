#include "render/vector/vector_canvas.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace collide::render {
namespace {

constexpr double kFullTurn = 2.0 * std::numbers::pi;

void setColor(cairo_t* cr, const frame::Rgba& c) {
  cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a);  // straight alpha, as the GL painter's colours
}

}  // namespace

VectorCanvas::~VectorCanvas() {
  // Leaves `cr` as it was given, even when drawing stopped half-way.
  if (open_) cairo_restore(cr_);
}

void VectorCanvas::clear() {
  closeBatch();
  pending_text_.clear();
}

void VectorCanvas::closeBatch() {
  if (!open_) return;
  for (const auto& [line, color] : pending_text_) vector_text_.draw(cr_, line, color);
  pending_text_.clear();
  cairo_restore(cr_);
  open_ = false;
}

void VectorCanvas::beginBatch(std::optional<frame::PixelRect> clip) {
  closeBatch();
  cairo_save(cr_);
  open_ = true;
  if (!clip) return;
  // Whole pixels covering the rectangle, as the GL painter's scissor.
  const double x0 = std::max(0.0, std::floor(clip->x0));
  const double x1 = std::min<double>(frame_w_, std::ceil(clip->x1));
  const double y0 = std::max(0.0, std::floor(clip->y0));
  const double y1 = std::min<double>(frame_h_, std::ceil(clip->y1));
  cairo_rectangle(cr_, x0, y0, std::max(0.0, x1 - x0), std::max(0.0, y1 - y0));
  cairo_clip(cr_);
}

void VectorCanvas::finish() {
  closeBatch();
}

frame::PixelRect VectorCanvas::text(std::string_view text, const core::Vec2& anchor_px,
                                    double size_px, const frame::Rgba& color, HAlign h, VAlign v) {
  PlacedLine line = painter().place(text, anchor_px, size_px, h, v);
  const frame::PixelRect box = line.box;
  pending_text_.emplace_back(std::move(line), color);
  return box;
}

void VectorCanvas::CairoSink::fill(const frame::Rgba& color, cairo_fill_rule_t rule) {
  setColor(cr_, color);
  cairo_set_fill_rule(cr_, rule);
  cairo_fill(cr_);
}

void VectorCanvas::CairoSink::stroke(double width_px, const frame::Rgba& color,
                                     cairo_line_join_t join) {
  setColor(cr_, color);
  cairo_set_line_width(cr_, width_px);
  cairo_set_line_cap(cr_, CAIRO_LINE_CAP_BUTT);
  cairo_set_line_join(cr_, join);
  cairo_stroke(cr_);
}

void VectorCanvas::CairoSink::fillAndOutline(double outline_px, const frame::Rgba& fill_color,
                                             const frame::Rgba& edge) {
  if (outline_px <= 0.0) {
    fill(fill_color);
    return;
  }
  setColor(cr_, fill_color);
  cairo_set_fill_rule(cr_, CAIRO_FILL_RULE_WINDING);
  cairo_fill_preserve(cr_);
  stroke(outline_px, edge, CAIRO_LINE_JOIN_MITER);
}

void VectorCanvas::CairoSink::addTriangle(const core::Vec2& a, const core::Vec2& b,
                                          const core::Vec2& c, const frame::Rgba& color) {
  cairo_move_to(cr_, a.x(), a.y());
  cairo_line_to(cr_, b.x(), b.y());
  cairo_line_to(cr_, c.x(), c.y());
  cairo_close_path(cr_);
  fill(color);
}

void VectorCanvas::CairoSink::addRect(const frame::PixelRect& r, const frame::Rgba& color) {
  if (r.width() <= 0.0 || r.height() <= 0.0) return;
  cairo_rectangle(cr_, r.x0, r.y0, r.width(), r.height());
  fill(color);
}

void VectorCanvas::CairoSink::addRectFrame(const frame::PixelRect& outer, double thickness_px,
                                           const frame::Rgba& color) {
  const double t = std::min({thickness_px, 0.5 * outer.width(), 0.5 * outer.height()});
  if (t <= 0.0) return;
  cairo_rectangle(cr_, outer.x0, outer.y0, outer.width(), outer.height());
  cairo_rectangle(cr_, outer.x0 + t, outer.y0 + t, outer.width() - 2.0 * t,
                  outer.height() - 2.0 * t);
  fill(color, CAIRO_FILL_RULE_EVEN_ODD);
}

void VectorCanvas::CairoSink::addDisk(const core::Vec2& c, double radius_px,
                                      const frame::Rgba& color) {
  if (radius_px <= 0.0) return;
  cairo_new_path(cr_);
  cairo_arc(cr_, c.x(), c.y(), radius_px, 0.0, kFullTurn);
  fill(color);
}

void VectorCanvas::CairoSink::addRing(const core::Vec2& c, double outer_px, double inner_px,
                                      const frame::Rgba& color) {
  inner_px = std::max(0.0, inner_px);
  if (outer_px <= inner_px) return;
  cairo_new_path(cr_);
  cairo_arc(cr_, c.x(), c.y(), outer_px, 0.0, kFullTurn);
  if (inner_px > 0.0) {
    cairo_new_sub_path(cr_);
    cairo_arc(cr_, c.x(), c.y(), inner_px, 0.0, kFullTurn);
  }
  fill(color, CAIRO_FILL_RULE_EVEN_ODD);
}

void VectorCanvas::CairoSink::addArrow(const core::Vec2& tail, const core::Vec2& direction,
                                       double length_px, double shaft_px, double head_length_px,
                                       double head_width_px, const frame::Rgba& color) {
  if (length_px <= 0.0) return;
  // The GL painter's shaft quad and head triangle as one outline.
  const core::Vec2 along = direction.normalized();
  const core::Vec2 across{-along.y(), along.x()};
  const double head_length = std::min(head_length_px, length_px);
  const core::Vec2 tip = tail + length_px * along;
  const core::Vec2 head_base = tip - head_length * along;
  const double shaft_half = 0.5 * shaft_px, head_half = 0.5 * head_width_px;
  std::vector<core::Vec2> outline;
  if (length_px > head_length) {
    outline = {tail - shaft_half * across, head_base - shaft_half * across};
  }
  outline.push_back(head_base - head_half * across);
  outline.push_back(tip);
  outline.push_back(head_base + head_half * across);
  if (length_px > head_length) {
    outline.push_back(head_base + shaft_half * across);
    outline.push_back(tail + shaft_half * across);
  }
  cairo_new_path(cr_);
  for (const core::Vec2& p : outline) cairo_line_to(cr_, p.x(), p.y());
  cairo_close_path(cr_);
  fill(color);
}

void VectorCanvas::CairoSink::addLine(const core::Vec2& a, const core::Vec2& b, double thickness_px,
                                      const frame::Rgba& color) {
  if ((b - a).norm() <= 0.0 || thickness_px <= 0.0) return;
  cairo_move_to(cr_, a.x(), a.y());
  cairo_line_to(cr_, b.x(), b.y());
  stroke(thickness_px, color, CAIRO_LINE_JOIN_MITER);
}

void VectorCanvas::CairoSink::addPolyline(const std::vector<core::Vec2>& points,
                                          double thickness_px, const frame::Rgba& color,
                                          double dash_px) {
  if (points.size() < 2 || thickness_px <= 0.0) return;
  cairo_new_path(cr_);
  for (const core::Vec2& p : points) cairo_line_to(cr_, p.x(), p.y());
  if (dash_px > 0.0) {
    const double dashes[2] = {dash_px, dash_px};
    cairo_set_dash(cr_, dashes, 2, 0.0);
  }
  // One path with round joins, as the GL painter's chain.
  stroke(thickness_px, color, CAIRO_LINE_JOIN_ROUND);
  cairo_set_dash(cr_, nullptr, 0, 0.0);
}

void VectorCanvas::CairoSink::addPolyline(const std::vector<core::Vec2>& points,
                                          double thickness_px,
                                          const std::vector<frame::Rgba>& segment_colors) {
  // Segments of their own colours, square ends meeting at the points (a fading trail).
  for (std::size_t i = 1; i < points.size() && i - 1 < segment_colors.size(); ++i) {
    addLine(points[i - 1], points[i], thickness_px, segment_colors[i - 1]);
  }
}

void VectorCanvas::CairoSink::addSector(const core::Vec2& c, double radius_px, double from_rad,
                                        double to_rad, const frame::Rgba& color) {
  if (radius_px <= 0.0 || to_rad <= from_rad) return;
  cairo_move_to(cr_, c.x(), c.y());
  cairo_arc(cr_, c.x(), c.y(), radius_px, from_rad, to_rad);
  cairo_close_path(cr_);
  fill(color);
}

void VectorCanvas::CairoSink::addOutlinedDisk(const core::Vec2& c, double radius_px,
                                              double outline_px, const frame::Rgba& fill_color,
                                              const frame::Rgba& edge) {
  if (radius_px <= 0.0) return;
  const double t = std::clamp(outline_px, 0.0, radius_px);
  // The outline's centre line, stroked as wide as the band: its outer edge is the body's.
  cairo_new_path(cr_);
  cairo_arc(cr_, c.x(), c.y(), radius_px - 0.5 * t, 0.0, kFullTurn);
  fillAndOutline(t, fill_color, edge);
}

void VectorCanvas::CairoSink::addOutlinedRect(const frame::PixelRect& outer, double outline_px,
                                              const frame::Rgba& fill_color,
                                              const frame::Rgba& edge) {
  if (outer.width() <= 0.0 || outer.height() <= 0.0) return;
  const double t = std::clamp(outline_px, 0.0, 0.5 * std::min(outer.width(), outer.height()));
  cairo_rectangle(cr_, outer.x0 + 0.5 * t, outer.y0 + 0.5 * t, outer.width() - t,
                  outer.height() - t);
  fillAndOutline(t, fill_color, edge);
}

}  // namespace collide::render
