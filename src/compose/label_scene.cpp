#include "compose/label_scene.hpp"

#include <algorithm>
#include <optional>
#include <utility>

#include "compose/placement_obstacles.hpp"
#include "frame/mark_sizes.hpp"

namespace collide::compose {

namespace {

// Text keeps inside the world's clip and, like the title (FrameLayout::header, at the frame's
// margin from its top left corner), the frame's margin from every edge: the world may stray
// into the margin (an arrow over a tall body), a label there looks pushed out of the frame.
Box textClip(const frame::PanelLayout& where, const frame::FrameLayout& layout, bool in_margin) {
  const frame::PixelRect& clip = where.world_clip;
  const double margin = in_margin ? 0.0 : layout.header.x0;
  return {std::max(clip.x0, margin), std::max(clip.y0, margin),
          std::min(clip.x1, layout.width_px - margin),
          std::min(clip.y1, layout.height_px - margin)};
}

Box boundsOf(const frame::BodyModel& body, const frame::WorldToPixel& to_px) {
  const core::Vec2 c = to_px.toPixel(body.center_m);
  const double hx = to_px.px_per_m * body.half_extent_m.x();
  const double hy =
      body.shape == frame::BodyShape::kDisk ? hx : to_px.px_per_m * body.half_extent_m.y();
  return Box{c.x() - hx, c.y() - hy, c.x() + hx, c.y() + hy};
}

// The bodies and their velocity arrows, as the painter draws them.
void addBodies(LabelScene& scene, const frame::PanelModel& panel, const frame::FrameLayout& layout,
               const frame::WorldToPixel& to_px) {
  Obstacles& obstacles = scene.obstacles;
  for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
    const frame::BodyModel& body = panel.bodies[i];
    const Box bounds = boundsOf(body, to_px);
    obstacles.addBody({body.shape == frame::BodyShape::kDisk, bounds});
    scene.moves_with.push_back(body.moves_with);
    scene.arrows.emplace_back();
    // The velocity arrow, as the painter draws it.
    const double speed = body.velocity_mps.norm();
    if (speed > kRestSpeed_mps && panel.arrow_m_per_mps > 0.0 && body.moves_with < 0) {
      const core::Vec2 d{body.velocity_mps.x() / speed, -body.velocity_mps.y() / speed};
      const frame::ArrowShape arrow = frame::bodyArrowShape(body, panel, layout, to_px);
      const core::Vec2 tail = frame::bodyArrowTailPx(body, panel, layout, to_px, arrow);
      const core::Vec2 tip = tail + arrow.length_px * d;
      obstacles.addMark({tail, tip, 0.5 * layout.arrow_head_width_px + 1.0}, static_cast<int>(i));
      scene.arrows.back() = std::pair{tail, tip};
    }
  }
}

// The strobe's images, the contact flashes and the centre of mass.
void addMarks(Obstacles& obstacles, const frame::PanelModel& panel,
              const frame::FrameLayout& layout, const frame::WorldToPixel& to_px) {
  for (const frame::BodyModel& ghost : panel.ghosts) {
    const Box bounds = boundsOf(ghost, to_px);
    if (ghost.shape == frame::BodyShape::kDisk) {
      obstacles.addMark({bounds.center(), bounds.center(), 0.5 * (bounds.x1 - bounds.x0)});
    } else {
      obstacles.addRegion(bounds);
    }
  }
  for (const frame::FlashModel& flash : panel.flashes) {
    const core::Vec2 c = to_px.toPixel(flash.center_m);
    obstacles.addMark({c, c, frame::flashRadiusPx(flash, layout, to_px)});
  }
  if (panel.center_of_mass_m) {
    const core::Vec2 c = to_px.toPixel(*panel.center_of_mass_m);
    obstacles.addMark({c, c, frame::kCenterOfMassRadius * layout.scale_px + 1.0});
  }
}

// The walls with their hatching.
void addWalls(Obstacles& obstacles, const frame::PanelModel& panel, const frame::PanelLayout& where,
              const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
              const frame::PixelRect& area) {
  const frame::PixelRect& clip = where.world_clip;
  const double wall_half = 2.0 * layout.track_px + frame::kWallHatchLength * layout.scale_px;
  for (const frame::WallModel& wall : panel.walls) {
    const core::Vec2 p = to_px.toPixel(wall.point_m);
    if (!panel.two_d) {
      const double track_y = to_px.toPixel({0.0, panel.track_y_m}).y();
      obstacles.addMark({{p.x(), track_y}, {p.x(), area.y0}, wall_half});
    } else {
      const core::Vec2 along{wall.normal.y(), wall.normal.x()};  // pixel y flips
      const double reach = 2.0 * (clip.width() + clip.height());
      obstacles.addMark({p - reach * along, p + reach * along, wall_half});
    }
  }
}

// Bodies on strings: every text keeps clear of the strings, their pivots and the beams they hang
// from (a note struck through by a string is hard to read, as any label is), and of the lines of
// a dimension (its text is placed first, in placePanel).
void addSuspension(Obstacles& obstacles, const frame::PanelModel& panel,
                   const frame::FrameLayout& layout, const frame::WorldToPixel& to_px) {
  const double string_half = 0.5 * frame::stringThicknessPx(layout) + 1.0;
  for (const frame::StringModel& string : panel.suspension.strings) {
    const core::Vec2 pivot = to_px.toPixel(string.pivot_m);
    obstacles.addMark({pivot, to_px.toPixel(string.body_m), string_half});
    obstacles.addMark({pivot, pivot, frame::pivotRadiusPx(layout) + 1.0});
  }
  for (const frame::SupportModel& support : panel.suspension.supports) {
    const frame::PixelRect beam = frame::supportBoxPx(support, layout, to_px);
    obstacles.addRegion({beam.x0, beam.y0, beam.x1, beam.y1});
  }
  for (const frame::DimensionModel& dim : panel.dimensions) {
    const frame::DimensionGeometry g = frame::dimensionGeometry(dim, layout, to_px);
    for (const frame::PixelSegment& line : g.lines) {
      obstacles.addMark({line.a, line.b, 0.5 * g.thin_px + 1.0});
    }
  }
}

// The axes the painter draws (none where fewer than two ticks fall), with their numbers.
void addRuler(Obstacles& obstacles, const frame::PanelModel& panel, const frame::PanelLayout& where,
              const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
              const frame::PixelRect& area, double small_line_px) {
  const double h = layout.scale_px;  // what the painter scales its marks by
  const frame::PixelRect& clip = where.world_clip;
  const frame::RulerPlacement ruler = frame::rulerPlacement(panel, where, layout, to_px, area);
  if (!ruler.along_x.ticks_m.empty()) {
    // The axis, its ticks and the numbers under them (as drawRuler sets them); the room under
    // the numbers stays free for a legend.
    const double numbers_bottom =
        ruler.x_axis_y_px + frame::kRulerTickLength * h + 0.2 * layout.small_px + small_line_px;
    obstacles.addRegion({clip.x0, ruler.x_axis_y_px - 1.0, clip.x1, numbers_bottom + 1.0});
  }
  if (!ruler.along_y.ticks_m.empty()) {
    const double x = ruler.y_axis_x_px;
    const double numbers = 2.5 * layout.small_px + frame::kRulerTickLength * h + layout.gap_px;
    const double top = to_px.toPixel({0.0, ruler.along_y.to_m}).y() - layout.small_px;
    const double bottom = to_px.toPixel({0.0, ruler.along_y.from_m}).y() + layout.small_px;
    obstacles.addRegion({x - numbers, top, x + 1.0, bottom});
  }
}

}  // namespace

LabelScene describePanel(const frame::PanelModel& panel, const frame::PanelLayout& where,
                         const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
                         const frame::PixelRect& area, double small_line_px, bool in_margin) {
  LabelScene scene{Obstacles(textClip(where, layout, in_margin), 0.5 * layout.gap_px,
                             kTextGapAcrossEm * layout.text_px, kTextGapAlongEm * layout.text_px),
                   {},
                   {},
                   layout.text_px};
  Obstacles& obstacles = scene.obstacles;
  addBodies(scene, panel, layout, to_px);
  addMarks(obstacles, panel, layout, to_px);
  addWalls(obstacles, panel, where, layout, to_px, area);
  addSuspension(obstacles, panel, layout, to_px);
  if (panel.draw_track) {
    const frame::PixelRect& clip = where.world_clip;
    const double y = to_px.toPixel({0.0, panel.track_y_m}).y();
    obstacles.addRegion({clip.x0, y - 1.0, clip.x1, y + layout.track_px + 1.0});
  }
  if (frame::drawsRuler(panel, where, layout)) {
    addRuler(obstacles, panel, where, layout, to_px, area, small_line_px);
  }
  if (const std::optional<frame::PixelRect> inset = frame::momentumBox(panel, where, layout)) {
    obstacles.addRegion({inset->x0, inset->y0, inset->x1, inset->y1});
  }
  return scene;
}

}  // namespace collide::compose
