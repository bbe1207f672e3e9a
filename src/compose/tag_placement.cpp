#include "compose/tag_placement.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "render/mark_sizes.hpp"

namespace collide::compose {
namespace {

constexpr int kTagDirections = 16;  // around the body, from its upper right
constexpr int kTagRings = 3;        // distances from its edge

}  // namespace

void placeTagsBeside(render::PanelModel& panel, const std::vector<bool>& named,
                     const std::vector<std::optional<std::pair<core::Vec2, core::Vec2>>>& arrows,
                     const render::FrameLayout& layout, const render::WorldToPixel& to_px,
                     render::TextMeasure& metrics, Obstacles& obstacles) {
  const double size = layout.small_px;
  const double height = metrics.ascender(size) + metrics.descender(size);
  const std::vector<BodyOutline>& outlines = obstacles.bodies();
  for (std::size_t i = 0; i < panel.bodies.size() && i < named.size() && i < outlines.size(); ++i) {
    render::BodyModel& body = panel.bodies[i];
    body.tag_at.reset();
    if (!named[i] || body.tag.empty() || render::tagFitsInside(body, layout, to_px)) continue;
    const double width = metrics.width(body.tag, size);
    const Box& bounds = outlines[i].bounds;
    const core::Vec2 c = bounds.center();
    const double radius = 0.5 * std::max(bounds.x1 - bounds.x0, bounds.y1 - bounds.y0);
    for (int r = 0; r < kTagRings && !body.tag_at; ++r) {
      const double d = obstacles.bodyGap() + 1.0 + r * 0.5 * height;
      for (int k = 0; k < kTagDirections; ++k) {
        // From the upper right (where a subscript's number reads), round both ways.
        const int step = (k + 1) / 2 * (k % 2 == 0 ? 1 : -1);
        const double angle =
            std::numbers::pi / 4.0 + 2.0 * std::numbers::pi * step / kTagDirections;
        const core::Vec2 u{std::cos(angle), -std::sin(angle)};
        const double m = std::max(std::abs(u.x()), std::abs(u.y()));
        // The box touches the circle of radius `radius + d` from outside, on the side u points to.
        const core::Vec2 near = c + (radius + d) * u;
        const double x0 = near.x() - 0.5 * width + 0.5 * width * u.x() / m;
        const double y0 = near.y() - 0.5 * height + 0.5 * height * u.y() / m;
        const Box box{x0, y0, x0 + width, y0 + height};
        if (!obstacles.isFree(box)) continue;
        const double own = outlines[i].distanceTo(box);
        bool nearest = true;
        for (std::size_t k2 = 0; k2 < outlines.size() && nearest; ++k2) {
          if (k2 != i && panel.bodies[k2].moves_with != static_cast<int>(i)) {
            nearest = outlines[k2].distanceTo(box) > own + 1.0;
            if (k2 < arrows.size() && arrows[k2]) {
              nearest = nearest && distance(box, arrows[k2]->first, arrows[k2]->second) > own + 1.0;
            }
          }
        }
        if (!nearest) continue;
        body.tag_at = render::PlacedText{{box.x0, box.y0}, {width, height}, std::nullopt};
        obstacles.addText(box);
        break;
      }
    }
  }
}

}  // namespace collide::compose
