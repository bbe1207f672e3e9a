#include "compose/dimension_placement.hpp"

#include <algorithm>

namespace collide::compose {
namespace {

// Sizes the painter draws a dimension with, as fractions of the layout scale
// (render/draw_strings.cpp), and the notes' line spacing, of the text size.
constexpr double kDimensionHead = 0.018;
constexpr double kExtensionOverrun = 0.012;
constexpr double kNoteLineSpacing = 1.3;

render::PixelRect boxAt(double x0, double y0, double width, double height) {
  return {x0, y0, x0 + width, y0 + height};
}

bool apart(const render::PixelRect& a, const render::PixelRect& b, double pad) {
  return a.x1 + pad <= b.x0 || b.x1 + pad <= a.x0 || a.y1 + pad <= b.y0 || b.y1 + pad <= a.y0;
}

}  // namespace

std::vector<PixelSegment> dimensionLines(const render::DimensionModel& dim,
                                         const render::FrameLayout& layout,
                                         const render::WorldToPixel& to_px) {
  const core::Vec2 low = to_px.toPixel(dim.low_m), high = to_px.toPixel(dim.high_m);
  const double x = to_px.toPixel({dim.line_x_m, 0.0}).x();
  const double over = kExtensionOverrun * layout.scale_px;
  return {{{std::min(low.x(), x), low.y()}, {x + over, low.y()}},
          {{std::min(high.x(), x), high.y()}, {x + over, high.y()}},
          {{x, low.y()}, {x, high.y()}}};
}

std::vector<render::PixelRect> placeDimensionTexts(
    render::SuspensionModel& suspension, const render::FrameLayout& layout,
    const render::WorldToPixel& to_px, const render::PixelRect& clip, render::TextMetrics& metrics,
    const std::function<bool(const render::PixelRect&)>& is_free) {
  std::vector<render::PixelRect> taken;
  const double size = layout.text_px, gap = layout.gap_px;
  const double line = metrics.ascender(size) + metrics.descender(size);
  const auto free = [&](const render::PixelRect& box) {
    if (box.x0 < clip.x0 || box.y0 < clip.y0 || box.x1 > clip.x1 || box.y1 > clip.y1) return false;
    for (const render::PixelRect& other : taken) {
      if (!apart(box, other, gap)) return false;
    }
    return is_free(box);
  };
  for (render::DimensionModel& dim : suspension.dimensions) {
    dim.label_at.reset();
    dim.notes_at_px.reset();
    const core::Vec2 low = to_px.toPixel(dim.low_m), high = to_px.toPixel(dim.high_m);
    const double x = to_px.toPixel({dim.line_x_m, 0.0}).x();
    const double side = 0.6 * kDimensionHead * layout.scale_px;
    if (!dim.label.empty()) {
      // Beside the middle of the line, right then left; then beside its ends.
      const double w = metrics.width(dim.label, size);
      const double mid = 0.5 * (low.y() + high.y()) - 0.5 * line;
      const std::vector<render::PixelRect> candidates = {
          boxAt(x + side, mid, w, line),
          boxAt(x - side - w, mid, w, line),
          boxAt(x + side, std::min(low.y(), high.y()) - line - gap, w, line),
          boxAt(x + side, std::max(low.y(), high.y()) + gap, w, line),
          boxAt(x - side - w, std::min(low.y(), high.y()) - line - gap, w, line),
          boxAt(x - side - w, std::max(low.y(), high.y()) + gap, w, line)};
      const auto pick = std::find_if(candidates.begin(), candidates.end(), free);
      if (pick == candidates.end()) {
        dim.label.clear();  // gives way, as a crowded body's label does: the line still shows h
      } else {
        dim.label_at = render::PlacedText{{pick->x0, pick->y0}, {w, line}, std::nullopt};
        taken.push_back(*pick);
      }
    }
    if (dim.notes.empty()) continue;
    double w = 0.0;
    for (const std::string& note : dim.notes) w = std::max(w, metrics.width(note, size));
    const double h = kNoteLineSpacing * size * static_cast<double>(dim.notes.size() - 1) + line;
    const core::Vec2 chosen = to_px.toPixel(dim.notes_m);
    const std::vector<render::PixelRect> candidates = {
        boxAt(chosen.x(), chosen.y(), w, h), boxAt(clip.x0 + gap, clip.y0 + gap, w, h),
        boxAt(clip.x1 - gap - w, clip.y0 + gap, w, h),
        boxAt(clip.x0 + gap, clip.y1 - gap - h, w, h),
        boxAt(clip.x1 - gap - w, clip.y1 - gap - h, w, h)};
    const auto pick = std::find_if(candidates.begin(), candidates.end(), free);
    if (pick == candidates.end()) continue;
    dim.notes_at_px = core::Vec2{pick->x0, pick->y0};
    taken.push_back(*pick);
  }
  return taken;
}

}  // namespace collide::compose
