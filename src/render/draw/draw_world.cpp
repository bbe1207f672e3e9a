// SPDX-License-Identifier: MIT
// The scene of one panel: walls, track, trails, bodies, bonds, springs, arrows, the centre of
// mass and contact flashes, in the order they are drawn; its strobe images
// (draw_strobe_images.cpp), labels (draw_world_labels.cpp) and ruler (draw_ruler.cpp) beside it.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <string_view>

#include "frame/mark_sizes.hpp"
#include "render/draw/draw_world_parts.hpp"
#include "render/draw/frame_drawing.hpp"

namespace collide::render {
namespace {

// Fractions of the frame height (the marks labels keep clear of: frame/mark_sizes.hpp).
constexpr double kBond = 0.012;        // thickness of a stuck-cluster link
constexpr double kTrailAlpha = 0.7;    // newest end of a trail
constexpr double kSpringLine = 0.005;  // thickness of a soft contact's spring, of frame height

}  // namespace

frame::Rgba outlineOf(const frame::Rgba& fill, const frame::FrameStyle& style) {
  const auto shade = [&](float c) { return std::clamp(c * style.outline_shade, 0.0f, 1.0f); };
  return {shade(fill.r), shade(fill.g), shade(fill.b), fill.a};
}

// The id of body `index`'s item of this kind (frame/drawn_items.hpp): "velocity.2".
std::string bodyId(std::string_view what, std::size_t index) {
  return std::string(what) + "." + std::to_string(index + 1);
}

// Pixel direction of a world vector (y flips).
core::Vec2 pixelDirection(const core::Vec2& world) {
  return {world.x(), -world.y()};
}

bool seen(float opacity) {
  return opacity >= 1.0f / 255.0f;
}

frame::Rgba faded(const frame::Rgba& color, float opacity) {
  return {color.r, color.g, color.b, color.a * std::clamp(opacity, 0.0f, 1.0f)};
}

Placed drawBody(const frame::BodyModel& body, const frame::FrameStyle& style,
                const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
                ShapeSink& mesh) {
  Placed placed;
  placed.center = to_px.toPixel(body.center_m);
  const double outline = layout.outline_px;
  const frame::Rgba edge = outlineOf(body.fill, style);
  if (body.shape == frame::BodyShape::kDisk) {
    const double radius = to_px.px_per_m * body.half_extent_m.x();
    mesh.addOutlinedDisk(placed.center, radius, outline, body.fill, edge);
    if (body.show_orientation && radius > 2.0 * outline) {
      const core::Vec2 spoke{std::cos(body.angle_rad), -std::sin(body.angle_rad)};
      mesh.addLine(placed.center, placed.center + (radius - outline) * spoke, 1.5 * outline, edge);
    }
    placed.radius = radius;
    placed.top = placed.center.y() - radius;
    placed.bottom = placed.center.y() + radius;
    return placed;
  }
  const double half_w = to_px.px_per_m * body.half_extent_m.x();
  const double half_h = to_px.px_per_m * body.half_extent_m.y();
  const frame::PixelRect outer{placed.center.x() - half_w, placed.center.y() - half_h,
                               placed.center.x() + half_w, placed.center.y() + half_h};
  const double t = std::min({outline, half_w, half_h});
  mesh.addOutlinedRect(outer, t, body.fill, edge);
  placed.radius = std::min(half_w, half_h);
  placed.top = outer.y0;
  placed.bottom = outer.y1;
  return placed;
}

namespace {

void drawWall(const frame::WallModel& wall, const frame::PanelModel& panel,
              const frame::FrameStyle& style, const frame::FrameLayout& layout,
              const frame::WorldToPixel& to_px, const frame::PixelRect& area, ShapeSink& mesh) {
  const double h = layout.scale_px;
  const core::Vec2 n = pixelDirection(wall.normal).normalized();
  const core::Vec2 p = to_px.toPixel(wall.point_m);
  core::Vec2 a, b;
  if (!panel.two_d) {
    // 1D: a wall standing on the track, as tall as the world area.
    const double track_y = to_px.toPixel({0.0, panel.track_y_m}).y() + layout.track_px;
    a = {p.x(), track_y};
    b = {p.x(), area.y0};
  } else {
    // The wall's line, cut where it enters another wall's solid side (a box's corners), else
    // long enough to leave the scene (the scissor cuts it).
    const double reach_px = 2.0 * (area.width() + area.height());
    const double overlap_m = (2.0 * layout.track_px + frame::kWallHatchLength * h) / to_px.px_per_m;
    const core::Vec2 along_m{-wall.normal.y(), wall.normal.x()};
    double s0 = -reach_px / to_px.px_per_m, s1 = reach_px / to_px.px_per_m;
    for (const frame::WallModel& other : panel.walls) {
      const double denom = along_m.dot(other.normal);
      if (&other == &wall || std::abs(denom) < 1e-9) continue;
      const double s = (other.point_m - wall.point_m).dot(other.normal) / denom;
      if (denom > 0.0) s0 = std::max(s0, s - overlap_m);
      if (denom < 0.0) s1 = std::min(s1, s + overlap_m);
    }
    if (s1 <= s0) return;
    a = to_px.toPixel(wall.point_m + s0 * along_m);
    b = to_px.toPixel(wall.point_m + s1 * along_m);
  }
  const double thick = 2.0 * layout.track_px;
  mesh.addLine(a - 0.5 * thick * n, b - 0.5 * thick * n, thick, style.track);
  // Hatching on the solid side: short slanted strokes.
  const double spacing = frame::kWallHatchSpacing * h, length = frame::kWallHatchLength * h;
  const double span = (b - a).norm();
  const core::Vec2 unit = (b - a) / std::max(span, 1e-9);
  const core::Vec2 slant = (-n + unit).normalized();
  for (double s = 0.5 * spacing; s < span; s += spacing) {
    const core::Vec2 base = a + s * unit - thick * n;
    mesh.addLine(base, base + length * slant, 0.5 * layout.track_px, style.track);
  }
}

void drawTrail(const frame::BodyModel& body, const frame::FrameLayout& layout,
               const frame::WorldToPixel& to_px, ShapeSink& mesh) {
  const std::size_t n = body.trail_m.size();
  if (n < 2) return;
  // One polyline, fading towards its old end: its segments join without overlapping.
  std::vector<core::Vec2> points;
  std::vector<frame::Rgba> colors;
  for (std::size_t i = 0; i < n; ++i) {
    points.push_back(to_px.toPixel(body.trail_m[i]));
    if (i == 0) continue;
    const double start = std::min<double>(body.trail_start_alpha, kTrailAlpha);
    const double alpha =
        start + (kTrailAlpha - start) * static_cast<double>(i) / static_cast<double>(n - 1);
    colors.push_back(withAlpha(body.fill, alpha));
  }
  mesh.addPolyline(points, layout.line_px, colors);
}

// The classic quartered circle.
void drawCenterOfMass(const core::Vec2& c, const frame::FrameStyle& style,
                      const frame::FrameLayout& layout, ShapeSink& mesh) {
  const double r = frame::kCenterOfMassRadius * layout.scale_px;
  const double pi = std::numbers::pi;
  mesh.addDisk(c, r, style.background);
  mesh.addSector(c, r, 0.0, 0.5 * pi, style.text);
  mesh.addSector(c, r, pi, 1.5 * pi, style.text);
  mesh.addRing(c, r, r - std::max(1.0, 0.25 * r), style.text);
}

void drawFlash(const frame::FlashModel& flash, const frame::FrameStyle& style,
               const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
               ShapeSink& mesh) {
  const double s = std::clamp(flash.strength, 0.0, 1.0);
  if (s <= 0.0) return;
  const core::Vec2 c = to_px.toPixel(flash.center_m);
  const double outer = frame::flashRadiusPx(flash, layout, to_px);
  const double inner = 0.3 * outer;
  const frame::Rgba color = withAlpha(style.flash, s);
  const int spikes = 8;
  for (int i = 0; i < spikes; ++i) {
    const double a = 2.0 * std::numbers::pi * i / spikes;
    const double half = std::numbers::pi / spikes;
    mesh.addTriangle(c + inner * core::Vec2{std::cos(a - half), std::sin(a - half)},
                     c + outer * core::Vec2{std::cos(a), std::sin(a)},
                     c + inner * core::Vec2{std::cos(a + half), std::sin(a + half)}, color);
  }
  mesh.addDisk(c, inner, color);
}

void drawArrow(std::size_t index, const frame::PanelModel& panel, const frame::FrameStyle& style,
               const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
               ShapeSink& mesh) {
  const frame::BodyModel& body = panel.bodies[index];
  const double speed_mps = body.velocity_mps.norm();
  if (speed_mps <= kRestSpeed_mps || panel.arrow_m_per_mps <= 0.0 || body.moves_with >= 0) return;
  const frame::ArrowShape shape = frame::bodyArrowShape(body, panel, layout, to_px);
  const core::Vec2 direction = pixelDirection(body.velocity_mps) / speed_mps;
  const core::Vec2 tail = frame::bodyArrowTailPx(body, panel, layout, to_px, shape);
  const DrawnItemScope item(
      mesh, "arrow." + std::to_string(index + 1), "arrow", static_cast<int>(index),
      drawnArrow(tail, direction, shape, speed_mps, panel.arrow_m_per_mps * to_px.px_per_m));
  drawArrowShape(tail, direction, shape, style.arrow, mesh);
}

void drawWallsAndTrack(const frame::PanelModel& panel, const frame::FrameStyle& style,
                       const frame::PanelLayout& where, const frame::FrameLayout& layout,
                       const frame::WorldToPixel& to_px, const frame::PixelRect& area,
                       ShapeSink& mesh) {
  for (std::size_t k = 0; k < panel.walls.size(); ++k) {
    const DrawnItemScope item(mesh, "wall." + std::to_string(k + 1), "wall");
    drawWall(panel.walls[k], panel, style, layout, to_px, area, mesh);
  }
  if (!panel.draw_track) return;
  const DrawnItemScope item(mesh, "track", "track");
  // The line's top edge is the track, so blocks resting on it do not cover it.
  const double y = to_px.toPixel({0.0, panel.track_y_m}).y();
  mesh.addRect({where.world_clip.x0, y, where.world_clip.x1, y + layout.track_px}, style.track);
}

void drawBonds(const frame::PanelModel& panel, const std::vector<Placed>& placed,
               const frame::FrameStyle& style, const frame::FrameLayout& layout, ShapeSink& mesh) {
  for (const frame::BondModel& bond : panel.bonds) {
    if (bond.body_a < 0 || bond.body_b < 0 || bond.body_a >= static_cast<int>(placed.size()) ||
        bond.body_b >= static_cast<int>(placed.size()))
      continue;
    const core::Vec2 a = placed[bond.body_a].center, b = placed[bond.body_b].center;
    mesh.addLine(a, b, kBond * layout.scale_px, style.track);
    mesh.addDisk(a, kBond * layout.scale_px, style.track);
    mesh.addDisk(b, kBond * layout.scale_px, style.track);
  }
}

}  // namespace

// A zigzag of spring.turns turns between the ends, capped by short straight leads.
void drawSpring(const frame::SpringModel& spring, const frame::Rgba& color,
                const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
                ShapeSink& mesh) {
  const core::Vec2 a = to_px.toPixel(spring.from_m), b = to_px.toPixel(spring.to_m);
  const core::Vec2 along = b - a;
  const double length = along.norm();
  if (!(length > 1.0)) return;
  const core::Vec2 unit = along / length, across{-unit.y(), unit.x()};
  const double half_width =
      std::abs(to_px.toPixel(spring.from_m + core::Vec2{0.0, spring.half_width_m}).y() - a.y());
  const double lead = 0.1 * length;
  std::vector<core::Vec2> points = {a, a + lead * unit};
  const int turns = std::max(1, spring.turns);
  for (int k = 0; k < 2 * turns; ++k) {
    const double s = lead + (length - 2.0 * lead) * (k + 0.5) / (2 * turns);
    points.push_back(a + s * unit + (k % 2 == 0 ? 1.0 : -1.0) * half_width * across);
  }
  points.push_back(b - lead * unit);
  points.push_back(b);
  // Thin enough that the turns of a short spring stay apart.
  const double thickness =
      std::min(kSpringLine * layout.height_px, 0.5 * (length - 2.0 * lead) / (2 * turns));
  mesh.addPolyline(points, std::max(thickness, 1.0), color);
}

void drawArrowShape(const core::Vec2& tail_px, const core::Vec2& direction,
                    const frame::ArrowShape& shape, const frame::Rgba& color, ShapeSink& mesh) {
  if (shape.length_px <= 0.0) return;
  const core::Vec2 along = direction.normalized();
  if (shape.under_scale) {
    // Too short to read against the scale: one mark, the same in 1D and 2D, that no reader takes
    // for an arrow of some length: no shaft, only a bar across the base of a head ("|▶"), its
    // base where the minimum's visible part begins (a 2D body's edge, a 1D arrow's tail), so
    // its direction reads and its value stands in its readout.
    const double base = std::clamp(shape.mark_from_px, 0.0, shape.length_px);
    const core::Vec2 across{-along.y(), along.x()};
    const core::Vec2 at = tail_px + base * along;
    // The bar a little taller than the head and a shaft's width before it, so it reads apart.
    const core::Vec2 half_bar = 0.65 * shape.head_width_px * across;
    const double gap = std::max(1.5, shape.shaft_px);
    mesh.addLine(at - half_bar, at + half_bar, shape.shaft_px, color);
    mesh.addArrow(at + gap * along, along, shape.head_length_px, shape.shaft_px,
                  shape.head_length_px, shape.head_width_px, color);
    return;
  }
  if (!shape.off_scale) {
    mesh.addArrow(tail_px, along, shape.length_px, shape.shaft_px, shape.head_length_px,
                  shape.head_width_px, color);
    return;
  }
  // Off scale: the shaft broken, a slanted stroke across each side of the gap (like an axis
  // break), so the reader sees at once that this arrow is not to scale.
  const frame::ArrowBreak cut = frame::arrowBreak(shape);
  mesh.addLine(tail_px, tail_px + cut.break_start_px * along, shape.shaft_px, color);
  mesh.addArrow(tail_px + cut.break_end_px * along, along, shape.length_px - cut.break_end_px,
                shape.shaft_px, shape.head_length_px, shape.head_width_px, color);
  const core::Vec2 across{-along.y(), along.x()};
  const core::Vec2 slant = 0.6 * shape.head_width_px * (across + 0.5 * along).normalized();
  for (double at : {cut.break_start_px, cut.break_end_px}) {
    const core::Vec2 p = tail_px + at * along;
    mesh.addLine(p - slant, p + slant, std::max(1.0, 0.5 * shape.shaft_px), color);
  }
}

void drawPanelWorld(const frame::PanelModel& panel, const frame::FrameStyle& style,
                    const frame::PanelLayout& where, const frame::FrameLayout& layout,
                    Canvas& canvas) {
  ShapeSink& mesh = canvas.shapes();
  const frame::PixelRect area = frame::worldArea(panel, where, layout);
  const frame::WorldToPixel to_px = frame::fitView(panel.view, area);

  drawWallsAndTrack(panel, style, where, layout, to_px, area, mesh);
  if (panel.calibration) drawOriginCross(panel, style, layout, to_px, area, mesh);
  drawSuspensionUnder(panel.suspension, style, layout, to_px, mesh);
  for (const frame::BodyModel& body : panel.bodies) drawTrail(body, layout, to_px, mesh);
  std::vector<Placed> ghosts_at(panel.ghosts.size());
  drawGhosts(panel, false, style, layout, to_px, ghosts_at, mesh);

  // Contact flashes under the bodies, so a burst never hides a body (compose puts a 1D flash at
  // the top of the contact face, where half of it shows).
  for (std::size_t k = 0; k < panel.flashes.size(); ++k) {
    const DrawnItemScope item(mesh, "flash." + std::to_string(k + 1), "flash");
    drawFlash(panel.flashes[k], style, layout, to_px, mesh);
  }
  // Bodies moving with another (a bullet in its block) go last, so the one they sit in never
  // hides them.
  std::vector<Placed> placed(panel.bodies.size());
  for (bool riders : {false, true}) {
    for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
      if ((panel.bodies[i].moves_with >= 0) != riders) continue;
      const DrawnItemScope item(mesh, bodyId("body", i), "body", static_cast<int>(i));
      placed[i] = drawBody(panel.bodies[i], style, layout, to_px, mesh);
    }
  }
  // The edges of a strobe's images that a solid body would hide, over the bodies (under arrows).
  drawGhosts(panel, true, style, layout, to_px, ghosts_at, mesh);
  drawBonds(panel, placed, style, layout, mesh);
  for (const frame::SpringModel& spring : panel.springs)
    drawSpring(spring, style.arrow, layout, to_px, mesh);
  // Arrows after all bodies, so a neighbour never hides one.
  for (std::size_t i = 0; i < panel.bodies.size(); ++i)
    drawArrow(i, panel, style, layout, to_px, mesh);
  if (panel.center_of_mass_m) {
    drawCenterOfMass(to_px.toPixel(*panel.center_of_mass_m), style, layout, mesh);
  }
  // Compose placed the labels for a picture size and text floor (FrameShape::text_floor_px); a
  // painter of another size or floor places them here.
  const bool placed_here = panel.placed_for_width_px == layout.width_px &&
                           panel.placed_for_height_px == layout.height_px &&
                           panel.placed_for_scale_px == layout.scale_px;
  drawDimensions(panel.dimensions, style, layout, to_px, placed_here, canvas);

  // Text: tags inside strobe images (which block is which, where colours alone blur when faint),
  // inside bodies, then labels.
  drawGhostTags(panel, style, layout, to_px, ghosts_at, canvas);
  for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
    const frame::BodyModel& body = panel.bodies[i];
    if (body.tag.empty() || !frame::tagFitsInside(body, layout, to_px)) continue;
    if (!seen(body.tag_opacity)) continue;
    const DrawnItemScope item(mesh, bodyId("tag", i), "label", static_cast<int>(i));
    mesh.describeOpacity(body.tag_opacity);
    canvas.text(body.tag, frame::tagCenterPx(panel, i, placed[i].center, to_px), layout.small_px,
                faded(contrastingText(body.fill), body.tag_opacity), HAlign::kCenter,
                VAlign::kMiddle);
  }
  if (placed_here) {
    drawPlacedLabels(panel, style, layout, canvas);
  } else {
    drawOwnLabels(panel, style, where, layout, to_px, area, placed, canvas);
  }
  if (frame::drawsRuler(panel, where, layout)) {
    const DrawnItemScope item(mesh, "ruler", "scale");
    drawRuler(panel, style, where, layout, to_px, area, canvas);
  }
  if (panel.calibration && frame::drawsRuler(panel, where, layout)) {
    drawCalibrationStick(panel, style, where, layout, to_px, area, canvas);
  }
}

}  // namespace collide::render
