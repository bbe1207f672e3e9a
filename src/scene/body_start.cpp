// SPDX-License-Identifier: MIT
// How a body starts, as books state it: its size as a block's `width` or a disk's `radius`, its
// velocity as `speed` and `heading`, and its place as a target struck by another body
// (`struck_by`, `impact_parameter`, `gap`).
#include <cmath>

#include "scene/field_table.hpp"
#include "scene/heading.hpp"
#include "scene/reader_parts.hpp"
#include "scene/scene_io.hpp"

namespace collide::scene::detail {
namespace {

std::string vectorText(const core::Vec2& v, int dimensions) {
  if (dimensions == 1) return plainNumber(v.x());
  return "[" + plainNumber(v.x()) + ", " + plainNumber(v.y()) + "]";
}

// Half the extent of a body along a line: half a block's width, a disk's radius.
double halfExtent(const BodyDesc& body) {
  return body.shape == "disk" ? body.size_m : 0.5 * body.size_m;
}

}  // namespace

void readBodySize(Fields& f, BodyDesc& body) {
  const bool disk = body.shape == "disk";
  const char* own = disk ? "radius" : "width";
  const char* other = disk ? "width" : "radius";
  const Range& range = fieldRange("body", own);
  if (f.has(other)) {
    f.problem(f.node(other), other,
              "a " + body.shape + " has no " + other + "; allowed: " + own + " = " +
                  (disk ? "R (its radius)" : "W (its full width)"));
  }
  if (f.has(own) && f.has("size")) {
    f.problem(f.node("size"), "size",
              std::string("given with ") + own + "; allowed: " + own + " (or the older size)");
  }
  const char* key = f.has(own) ? own : "size";
  if (!f.has(own) && !f.has("size") && !f.has(other)) f.missing(own, range.text());
  body.size_m = f.number(key, range).value_or(0.5);
  if (f.has("size") && !f.has(own)) {
    f.note(f.keyPath("size") + ": read as the " + body.shape + "'s " + own +
           (disk ? "" : " (its full width)") + "; the clearer key is " + own);
  }
}

void readBodyVelocity(Fields& f, BodyDesc& body, int dimensions) {
  if (!f.has("speed")) {
    if (f.has("heading")) {
      f.problem(f.node("heading"), "heading", "needs a speed; allowed: with speed = V in m/s");
    }
    body.velocity_mps =
        f.vector("velocity", dimensions, kMaxSpeedMps, "a velocity in m/s", Quantity::kSpeed)
            .value_or(body.velocity_mps);
    return;
  }
  if (f.has("velocity")) {
    f.problem(f.node("speed"), "speed",
              "given with velocity; allowed: either velocity, or speed and heading");
    return;
  }
  const std::optional<double> speed = f.number("speed", fieldRange("body", "speed"));
  double heading_deg = 0.0;
  if (const toml::node* heading = f.node("heading")) {
    std::string why;
    const std::optional<double> degrees = headingDegrees(*heading, why);
    if (!degrees || !std::isfinite(*degrees) || std::abs(*degrees) > 360.0) {
      f.problem(heading, "heading", degrees ? "out of range; allowed: -360 to 360 degrees" : why);
      return;
    }
    heading_deg = *degrees;
    const bool along_x = std::remainder(heading_deg, 180.0) == 0.0;
    if (dimensions == 1 && !along_x) {
      f.problem(heading, "heading",
                "a 1D scene moves along x; allowed: 0 (\"E\", +x) or 180 (\"W\", -x)");
      return;
    }
  }
  if (!speed) return;
  body.velocity_mps = *speed * unitVectorAtDegrees(heading_deg);
  f.note(f.path() + ": velocity " + vectorText(body.velocity_mps, dimensions) + " m/s from speed " +
         plainNumber(*speed) + " m/s and heading " + plainNumber(heading_deg) + " degrees from +x");
}

std::optional<Aim> readAim(Fields& f, std::size_t body, int dimensions) {
  if (!f.has("struck_by")) {
    for (const char* key : {"impact_parameter", "gap"}) {
      if (f.has(key)) {
        f.problem(f.node(key), key,
                  "needs struck_by; allowed: with struck_by = N (the body "
                  "that strikes this one)");
      }
    }
    return std::nullopt;
  }
  if (f.has("position")) {
    f.problem(f.node("position"), "position",
              "given with struck_by; allowed: either position, or struck_by with "
              "impact_parameter and gap");
  }
  Aim aim;
  aim.body = body;
  aim.table = &f.table();
  aim.striker = f.node("struck_by");
  aim.gap_m = f.number("gap", fieldRange("body", "gap")).value_or(0.0);
  const toml::node* b = f.node("impact_parameter");
  if (b == nullptr) return aim;
  if (dimensions == 1) {
    f.problem(b, "impact_parameter", "a 1D collision is head-on; allowed: only in 2D scenes");
    return aim;
  }
  if (b->is_string()) {
    aim.b_length_m = f.number(
        "impact_parameter",
        {-kMaxLengthM, kMaxLengthM, false, "an impact parameter as a length", Quantity::kLength});
  } else {
    aim.b_fraction = f.number("impact_parameter", {-1.0, 1.0, false,
                                                   "an impact parameter as a fraction of the "
                                                   "summed radii (or a quoted length)"});
  }
  return aim;
}

// The target's place: touching the striker (or `gap` further on) along the line of approach
// (the striker's velocity relative to the target), its centre `b` to the right of that line.
void placeAimed(SceneDesc& scene, const Aim& aim, int striker, Fields& f) {
  const BodyDesc& from = scene.bodies[static_cast<std::size_t>(striker)];
  BodyDesc& target = scene.bodies[aim.body];
  const core::Vec2 relative = from.velocity_mps - target.velocity_mps;
  if (relative.norm() == 0.0) {
    f.problem(aim.striker, "struck_by",
              "body " + std::to_string(striker + 1) +
                  " does not move towards it (no relative velocity); allowed: a striker that "
                  "moves relative to this body");
    return;
  }
  const double reach = halfExtent(from) + halfExtent(target);
  const double b = aim.b_length_m ? *aim.b_length_m : aim.b_fraction.value_or(0.0) * reach;
  if (std::abs(b) > reach) {
    f.problem(f.node("impact_parameter"), "impact_parameter",
              "more than the summed radii (" + plainNumber(reach) +
                  " m), so they never touch; allowed: at most " + plainNumber(reach) + " m");
    return;
  }
  const core::Vec2 along = relative / relative.norm();
  const core::Vec2 right(along.y(), -along.x());
  const double ahead = std::sqrt(reach * reach - b * b) + aim.gap_m;
  target.position_m = from.position_m + ahead * along + b * right;
  if (scene.dimensions == 1) target.position_m.y() = 0.0;
  f.note(f.path() + ": position " + vectorText(target.position_m, scene.dimensions) +
         " m: struck by body " + std::to_string(striker + 1) + " ('" + from.name + "')" +
         (aim.gap_m == 0.0 ? ", touching it" : " after a gap of " + plainNumber(aim.gap_m) + " m") +
         (b == 0.0 ? ", head-on" : ", impact parameter " + plainNumber(b) + " m"));
}

}  // namespace collide::scene::detail
