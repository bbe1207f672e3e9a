#include "compose/dimension_placement.hpp"

#include <algorithm>
#include <vector>

#include "render/mark_sizes.hpp"

namespace collide::compose {
namespace {

constexpr double kNoteLineSpacing = 1.3;  // of the text size, as the painter draws the notes

Box boxAt(double x0, double y0, double width, double height) {
  return {x0, y0, x0 + width, y0 + height};
}

}  // namespace

void placeDimensionTexts(render::SuspensionModel& suspension, const render::FrameLayout& layout,
                         const render::WorldToPixel& to_px, render::TextMetrics& metrics,
                         Obstacles& obstacles) {
  const double size = layout.text_px, gap = layout.gap_px;
  const double line = metrics.ascender(size) + metrics.descender(size);
  const auto free = [&](const Box& box) { return obstacles.isFree(box); };
  const Box& clip = obstacles.clip();
  for (render::DimensionModel& dim : suspension.dimensions) {
    dim.label_at.reset();
    dim.notes_at_px.reset();
    const render::DimensionGeometry g = render::dimensionGeometry(dim, layout, to_px);
    const core::Vec2 &low = g.low_px, &high = g.high_px;
    const double x = g.line_x_px, side = 0.6 * g.head_px;
    if (!dim.label.empty()) {
      // Beside the middle of the line, right then left; then beside its ends.
      const double w = metrics.width(dim.label, size);
      const double mid = 0.5 * (low.y() + high.y()) - 0.5 * line;
      const std::vector<Box> candidates = {
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
        obstacles.addText(*pick);
      }
    }
    if (dim.notes.empty()) continue;
    double w = 0.0;
    for (const std::string& note : dim.notes) w = std::max(w, metrics.width(note, size));
    const double h = kNoteLineSpacing * size * static_cast<double>(dim.notes.size() - 1) + line;
    const core::Vec2 chosen = to_px.toPixel(dim.notes_m);
    const std::vector<Box> candidates = {boxAt(chosen.x(), chosen.y(), w, h),
                                         boxAt(clip.x0 + gap, clip.y0 + gap, w, h),
                                         boxAt(clip.x1 - gap - w, clip.y0 + gap, w, h),
                                         boxAt(clip.x0 + gap, clip.y1 - gap - h, w, h),
                                         boxAt(clip.x1 - gap - w, clip.y1 - gap - h, w, h)};
    const auto pick = std::find_if(candidates.begin(), candidates.end(), free);
    if (pick == candidates.end()) continue;
    dim.notes_at_px = core::Vec2{pick->x0, pick->y0};
    obstacles.addText(*pick);
  }
}

}  // namespace collide::compose
