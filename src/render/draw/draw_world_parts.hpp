// SPDX-License-Identifier: MIT
#pragma once
// Private to the panel's scene (draw_world.cpp, draw_world_labels.cpp, draw_strobe_images.cpp,
// draw_ruler.cpp): the pieces its files share.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "frame/frame_model.hpp"
#include "frame/layout.hpp"
#include "render/draw/canvas.hpp"

namespace collide::render {

frame::Rgba outlineOf(const frame::Rgba& fill, const frame::FrameStyle& style);

// The id of body `index`'s item of this kind (frame/drawn_items.hpp): "velocity.2".
std::string bodyId(std::string_view what, std::size_t index);

// Pixel direction of a world vector (y flips).
core::Vec2 pixelDirection(const core::Vec2& world);

// A text fading in or out (frame::PlacedText::opacity) is drawn in its colour with the alpha
// times its opacity. One below a single 8-bit step of alpha shows nothing: it is neither drawn
// nor recorded as an item (seen: false), so the layout lists only what can be seen.
bool seen(float opacity);
frame::Rgba faded(const frame::Rgba& color, float opacity);

struct Placed {
  core::Vec2 center;  // pixels
  double top = 0, bottom = 0, radius = 0;
};

Placed drawBody(const frame::BodyModel& body, const frame::FrameStyle& style,
                const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
                ShapeSink& mesh);

// A zigzag of spring.turns turns between the ends, capped by short straight leads.
void drawSpring(const frame::SpringModel& spring, const frame::Rgba& color,
                const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
                ShapeSink& mesh);

// The ruler along the scene's x axis, and in 2D along its y axis (draw_ruler.cpp).
void drawRuler(const frame::PanelModel& panel, const frame::FrameStyle& style,
               const frame::PanelLayout& where, const frame::FrameLayout& layout,
               const frame::WorldToPixel& to_px, const frame::PixelRect& area, Canvas& canvas);

// The bodies' labels (draw_world_labels.cpp).
// Labels where compose placed them (PlacedText), with their leader lines.
void drawPlacedLabels(const frame::PanelModel& panel, const frame::FrameStyle& style,
                      const frame::FrameLayout& layout, Canvas& canvas);
// Labels placed here, for a frame composed without a picture size: 1D in rows, 2D beside bodies.
void drawOwnLabels(const frame::PanelModel& panel, const frame::FrameStyle& style,
                   const frame::PanelLayout& where, const frame::FrameLayout& layout,
                   const frame::WorldToPixel& to_px, const frame::PixelRect& area,
                   const std::vector<Placed>& placed, Canvas& canvas);

// The strobe images and their numbers (draw_strobe_images.cpp).
// The strobe images, each where it lands, under the bodies (over_bodies: false), then the edges
// of those a solid body would hide (true): such an image's faint fill stays under the bodies, so a
// solid body keeps its own colour, and its edge is drawn over them, so its place still reads.
void drawGhosts(const frame::PanelModel& panel, bool over_bodies, const frame::FrameStyle& style,
                const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
                std::vector<Placed>& ghosts_at, ShapeSink& mesh);
// The strobe images' numbers, each inside its image; one a solid body lies over (over_bodies:
// only its edge shows there) has its number just above it, in its edge's colour, where no body
// covers it.
void drawGhostTags(const frame::PanelModel& panel, const frame::FrameStyle& style,
                   const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
                   const std::vector<Placed>& ghosts_at, Canvas& canvas);

}  // namespace collide::render
