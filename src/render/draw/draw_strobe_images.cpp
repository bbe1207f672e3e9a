// SPDX-License-Identifier: MIT
// A strobe's images in a panel's scene: their faint bodies and bumpers, the edges of those a solid
// body lies over, and their numbers.
#include <algorithm>
#include <string>
#include <vector>

#include "frame/mark_sizes.hpp"
#include "render/draw/draw_world_parts.hpp"
#include "render/draw/frame_drawing.hpp"

namespace collide::render {
namespace {

// A strobe image's number: the colour that reads on the image as drawn (its fill over the
// background), then faded towards that image as it is faded, so an early image's number is as
// faint as the image; at least kGhostTagLeast of the way, so the faintest still reads.
frame::Rgba ghostTagColour(const frame::Rgba& fill, const frame::FrameStyle& style) {
  constexpr float kGhostTagLeast = 0.45f;
  const float a = std::clamp(fill.a, 0.0f, 1.0f);
  const auto over = [&](float f, float b) { return b + (f - b) * a; };
  const frame::Rgba shown{over(fill.r, style.background.r), over(fill.g, style.background.g),
                          over(fill.b, style.background.b), 1.0f};
  const frame::Rgba text = contrastingText(shown);
  const float k = kGhostTagLeast + (1.0f - kGhostTagLeast) * a;
  return {shown.r + (text.r - shown.r) * k, shown.g + (text.g - shown.g) * k,
          shown.b + (text.b - shown.b) * k, 1.0f};
}

// The edge of a strobe image drawn over a solid body (a body's first image under its last): there
// its faint fill barely tints the body, so its whole edge is drawn opaque, in the body's own shade
// lined inside with the background, and reads over the body and over the paper alike.
void drawImageEdge(const frame::BodyModel& ghost, const frame::FrameStyle& style,
                   const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
                   ShapeSink& mesh) {
  frame::Rgba solid = ghost.fill;
  solid.a = 1.0f;
  const frame::Rgba edge = outlineOf(solid, style);
  const double t = layout.outline_px;
  const core::Vec2 center = to_px.toPixel(ghost.center_m);
  if (ghost.shape == frame::BodyShape::kDisk) {
    const double radius = to_px.px_per_m * ghost.half_extent_m.x();
    if (radius <= 2.0 * t) return;
    mesh.addRing(center, radius, radius - t, edge);
    mesh.addRing(center, radius - t, radius - 2.0 * t, style.background);
    return;
  }
  const double half_w = to_px.px_per_m * ghost.half_extent_m.x();
  const double half_h = to_px.px_per_m * ghost.half_extent_m.y();
  if (std::min(half_w, half_h) <= 2.0 * t) return;
  const frame::PixelRect outer{center.x() - half_w, center.y() - half_h, center.x() + half_w,
                               center.y() + half_h};
  mesh.addRectFrame(outer, t, edge);
  mesh.addRectFrame({outer.x0 + t, outer.y0 + t, outer.x1 - t, outer.y1 - t}, t, style.background);
}

}  // namespace

// The strobe images, each where it lands, under the bodies (over_bodies: false), then the edges
// of those a solid body would hide (true): such an image's faint fill stays under the bodies, so a
// solid body keeps its own colour, and its edge is drawn over them, so its place still reads.
void drawGhosts(const frame::PanelModel& panel, bool over_bodies, const frame::FrameStyle& style,
                const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
                std::vector<Placed>& ghosts_at, ShapeSink& mesh) {
  for (std::size_t g = 0; g < panel.ghosts.size(); ++g) {
    const frame::BodyModel& ghost = panel.ghosts[g];
    if (over_bodies) {
      if (!ghost.over_bodies) continue;
      const DrawnItemScope item(mesh, "image_edge." + std::to_string(g + 1), "image");
      drawImageEdge(ghost, style, layout, to_px, mesh);
      continue;
    }
    const DrawnItemScope item(mesh, "image." + std::to_string(g + 1), "image");
    ghosts_at[g] = drawBody(ghost, style, layout, to_px, mesh);
    frame::Rgba faint = style.arrow;
    faint.a *= ghost.fill.a;
    for (const frame::SpringModel& bumper : ghost.bumpers)
      drawSpring(bumper, faint, layout, to_px, mesh);
  }
}

// The strobe images' numbers, each inside its image; one a solid body lies over (over_bodies:
// only its edge shows there) has its number just above it, in its edge's colour, where no body
// covers it.
void drawGhostTags(const frame::PanelModel& panel, const frame::FrameStyle& style,
                   const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
                   const std::vector<Placed>& ghosts_at, Canvas& canvas) {
  for (std::size_t g = 0; g < panel.ghosts.size(); ++g) {
    const frame::BodyModel& ghost = panel.ghosts[g];
    if (ghost.tag.empty() || !frame::tagFitsInside(ghost, layout, to_px)) continue;
    if (ghost.over_bodies) {
      frame::Rgba edge = outlineOf(ghost.fill, style);
      edge.a = 1.0f;
      canvas.text(ghost.tag, {ghosts_at[g].center.x(), ghosts_at[g].top - 0.5 * layout.line_px},
                  layout.small_px, edge, HAlign::kCenter, VAlign::kBottom);
      continue;
    }
    canvas.text(ghost.tag, ghosts_at[g].center, layout.small_px, ghostTagColour(ghost.fill, style),
                HAlign::kCenter, VAlign::kMiddle);
  }
}

}  // namespace collide::render
