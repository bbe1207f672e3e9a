// SPDX-License-Identifier: MIT
#include "app/layout_json.hpp"

#include <cmath>
#include <string>

namespace collide::app {
namespace {

// Pixels to the hundredth: finer than any painter places, and the file stays small.
double px(double value) {
  return std::round(value * 100.0) / 100.0;
}

const char* drawnName(frame::ArrowDrawn drawn) {
  switch (drawn) {
    case frame::ArrowDrawn::kOffScale:
      return "off_scale";
    case frame::ArrowDrawn::kBelowScale:
      return "below_scale";
    case frame::ArrowDrawn::kOnScale:
      break;
  }
  return "on_scale";
}

// An opacity to the thousandth: finer than the 8-bit step of a pixel's alpha.
double opacity(double value) {
  return std::round(value * 1000.0) / 1000.0;
}

void writePoint(report::JsonWriter& json, const core::Vec2& point) {
  json.beginArray().value(px(point.x())).value(px(point.y())).endArray();
}

}  // namespace

void writeDrawnItem(report::JsonWriter& json, const frame::DrawnItem& item) {
  json.beginObject().key("id").value(item.id).key("kind").value(item.kind);
  if (!item.lines.empty()) {
    std::string text;
    for (const std::string& line : item.lines) text += (text.empty() ? "" : "\n") + line;
    json.key("text").value(text).key("lines").value(static_cast<int>(item.lines.size()));
  }
  json.key("box").beginArray();
  for (double v : {item.box.x0, item.box.y0, item.box.x1, item.box.y1}) json.value(px(v));
  json.endArray();
  if (item.body >= 0) json.key("body").value(item.body + 1);
  if (item.panel >= 0) json.key("panel").value(item.panel + 1);
  // Only a text fading in or out says how solid it is drawn.
  if (opacity(item.opacity) < 1.0) json.key("opacity").value(opacity(item.opacity));
  if (item.arrow) {
    const frame::DrawnArrow& arrow = *item.arrow;
    json.key("from");
    writePoint(json, arrow.from_px);
    json.key("to");
    writePoint(json, arrow.to_px);
    json.key("value").value(arrow.value_mps);
    json.key("scale").value(arrow.scale_px_per_mps);
    json.key("drawn").value(drawnName(arrow.drawn));
  }
  if (!item.path.empty()) {
    json.key("path").beginArray();
    for (const core::Vec2& point : item.path) writePoint(json, point);
    json.endArray();
  }
  if (item.stick) {
    json.key("stick").beginObject().key("from");
    writePoint(json, item.stick->from_px);
    json.key("to");
    writePoint(json, item.stick->to_px);
    json.key("length_m").value(item.stick->length_m);
    json.key("px_per_m").value(item.stick->px_per_m).endObject();
  }
  json.endObject();
}

}  // namespace collide::app
