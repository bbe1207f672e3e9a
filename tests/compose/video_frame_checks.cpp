// SPDX-License-Identifier: MIT
#include "video_frame_checks.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <string_view>

namespace collide::test {
namespace {

// Whether the segment from `a` to `b` runs through the inside of `box` (Liang-Barsky clipping:
// a part of it of positive length lies inside).
bool crosses(const core::Vec2& a, const core::Vec2& b, const frame::PixelRect& box) {
  double enter = 0.0, leave = 1.0;
  const core::Vec2 d = b - a;
  const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
  const double q[4] = {a.x() - box.x0, box.x1 - a.x(), a.y() - box.y0, box.y1 - a.y()};
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0.0) {
      if (q[k] <= 0.0) return false;
    } else if (p[k] < 0.0) {
      enter = std::max(enter, q[k] / p[k]);
    } else {
      leave = std::min(leave, q[k] / p[k]);
    }
  }
  return leave - enter > 1e-9;
}

bool holds(const frame::PixelRect& box, const core::Vec2& point) {
  return point.x() > box.x0 && point.x() < box.x1 && point.y() > box.y0 && point.y() < box.y1;
}

bool movesAlong(const std::string& kind) {
  return kind == "label" || kind == "readout" || kind == "legend";
}

core::Vec2 centre(const frame::PixelRect& box) {
  return {0.5 * (box.x0 + box.x1), 0.5 * (box.y0 + box.y1)};
}

// The least of |moved - carried| over a box's near edge, far edge and centre along one axis.
double nearestShift(double was0, double was1, double now0, double now1, double carried) {
  const double edges[3] = {now0 - was0, now1 - was1, 0.5 * (now0 + now1 - was0 - was1)};
  double least = HUGE_VAL;
  for (const double moved : edges) least = std::min(least, std::abs(moved - carried));
  return least;
}

// The box of body `body` of panel `panel` in `items`, if drawn.
const frame::PixelRect* bodyBox(const std::vector<frame::DrawnItem>& items, int panel, int body) {
  for (const frame::DrawnItem& item : items) {
    if (item.kind == "body" && item.panel == panel && item.body == body) return &item.box;
  }
  return nullptr;
}

}  // namespace

std::string arrowThroughSomething(const std::vector<frame::DrawnItem>& items) {
  for (const frame::DrawnItem& arrow : items) {
    if (arrow.kind != "arrow" || !arrow.arrow) continue;
    const frame::PixelRect* own = bodyBox(items, arrow.panel, arrow.body);
    for (const frame::DrawnItem& other : items) {
      if (other.panel != arrow.panel || (other.kind != "wall" && other.kind != "body")) continue;
      // Not the body itself, one it overlaps or is stuck to, nor one riding in it (a bullet in
      // its block, drawn over it).
      if (other.kind == "body" &&
          (other.body == arrow.body || holds(other.box, arrow.arrow->from_px) ||
           (own != nullptr && holds(*own, centre(other.box))))) {
        continue;
      }
      if (crosses(arrow.arrow->from_px, arrow.arrow->to_px, other.box)) {
        return arrow.id + " crosses " + other.id;
      }
    }
  }
  return {};
}

std::string arrowOffItsValue(const std::vector<frame::DrawnItem>& items) {
  for (const frame::DrawnItem& item : items) {
    if (!item.arrow || item.arrow->drawn != frame::ArrowDrawn::kOnScale) continue;
    const frame::DrawnArrow& arrow = *item.arrow;
    const double length_px = (arrow.to_px - arrow.from_px).norm();
    const double says_px = std::abs(arrow.value_mps) * arrow.scale_px_per_mps;
    if (std::abs(length_px - says_px) > kArrowPx) {
      std::ostringstream out;
      out << item.id << " is " << length_px << " px long for " << arrow.value_mps << " m/s at "
          << arrow.scale_px_per_mps << " px per m/s (" << says_px << " px)";
      return out.str();
    }
  }
  return {};
}

FrameItems frameItems(double t_s, const std::vector<frame::DrawnItem>& items) {
  FrameItems out;
  out.t_s = t_s;
  for (const frame::DrawnItem& item : items) {
    if (item.kind == "body" && item.body >= 0) out.bodies[{item.panel, item.body}] = item.box;
    if (movesAlong(item.kind)) out.texts[item.id] = item;
    // A chart's texts are its ticks and its series' names, not the lines of one text.
    if (!item.lines.empty() && item.kind != "chart") out.lines[item.id] = item.lines.size();
  }
  return out;
}

double movedBeyond(const frame::PixelRect& was, const frame::PixelRect& now,
                   const core::Vec2& carried) {
  const double across = nearestShift(was.x0, was.x1, now.x0, now.x1, carried.x());
  const double up_down = nearestShift(was.y0, was.y1, now.y0, now.y1, carried.y());
  return std::hypot(across, up_down);
}

namespace {

// The id of the same label by its body for a legend line's id, or in the legend for a label's
// ("panel2.legend.mass.1" and "panel2.mass.1"); empty for other texts.
std::string otherPlaceOf(const std::string& id) {
  constexpr std::string_view kLegend = "legend.";
  const std::size_t panel_end = id.rfind("panel", 0) == 0 ? id.find('.') + 1 : 0;
  const std::string panel = id.substr(0, panel_end), rest = id.substr(panel_end);
  if (rest.rfind(kLegend, 0) == 0) return panel + rest.substr(kLegend.size());
  if (rest.rfind("mass.", 0) == 0 || rest.rfind("velocity.", 0) == 0) {
    return panel + std::string(kLegend) + rest;
  }
  return {};
}

}  // namespace

std::vector<std::string> textsThatJump(const FrameItems& was, const FrameItems& now,
                                       double limit_px, TextsOf which) {
  std::vector<std::string> out;
  for (const auto& [id, text] : now.texts) {
    if ((text.body >= 0) != (which == TextsOf::kBodies)) continue;
    auto before = was.texts.find(id);
    // A label that leaves its body for its legend, or comes back, moves as one text: it is the
    // same words read somewhere else.
    if (before == was.texts.end()) {
      const std::string other = otherPlaceOf(id);
      if (!other.empty() && now.texts.count(other) == 0) before = was.texts.find(other);
    }
    if (before == was.texts.end()) continue;
    double moved = movedBeyond(before->second.box, text.box, {0.0, 0.0});
    const auto body_was = was.bodies.find({text.panel, text.body});
    const auto body_now = now.bodies.find({text.panel, text.body});
    if (text.body >= 0 && body_was != was.bodies.end() && body_now != now.bodies.end()) {
      const core::Vec2 carried = centre(body_now->second) - centre(body_was->second);
      moved = std::min(moved, movedBeyond(before->second.box, text.box, carried));
    }
    if (moved > limit_px) {
      std::ostringstream line;
      if (before->first != id) line << before->first << " becomes ";
      line << id << " moves " << moved << " px between t = " << was.t_s << " s and " << now.t_s
           << " s";
      out.push_back(line.str());
    }
  }
  return out;
}

std::vector<std::string> textsThatFadeTooFast(const FrameItems& was, const FrameItems& now) {
  std::set<std::string> ids;
  for (const auto& text : was.texts) ids.insert(text.first);
  for (const auto& text : now.texts) ids.insert(text.first);
  const auto opacity = [](const FrameItems& items, const std::string& id) {
    const auto text = items.texts.find(id);
    return text == items.texts.end() ? 0.0 : text->second.opacity;
  };
  std::vector<std::string> out;
  for (const std::string& id : ids) {
    const double before = opacity(was, id), after = opacity(now, id);
    const std::string other = otherPlaceOf(id);
    const bool twin_stays =
        !other.empty() && was.texts.count(other) != 0 && now.texts.count(other) != 0;
    const bool fading = (before > 0.0 && before < 1.0) || (after > 0.0 && after < 1.0);
    const bool comes_or_goes = (before == 0.0) != (after == 0.0);
    if (!(fading || (comes_or_goes && twin_stays))) continue;
    if (std::abs(after - before) <= kFadeStep) continue;
    std::ostringstream line;
    line << id << " fades from " << before << " to " << after << " between t = " << was.t_s
         << " s and " << now.t_s << " s";
    out.push_back(line.str());
  }
  return out;
}

std::vector<std::string> textsThatRewrap(const FrameItems& was, const FrameItems& now) {
  std::vector<std::string> out;
  for (const auto& [id, lines] : now.lines) {
    const auto before = was.lines.find(id);
    if (before == was.lines.end() || before->second == lines) continue;
    std::ostringstream line;
    line << id << " goes from " << before->second << " to " << lines
         << " lines between t = " << was.t_s << " s and " << now.t_s << " s";
    out.push_back(line.str());
  }
  return out;
}

}  // namespace collide::test
