#include "compose/suspension_view.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "compose/frame_text.hpp"
#include "text/number_format.hpp"
#include "text/translate.hpp"
#include "text/wording.hpp"

namespace collide::compose {
namespace {

constexpr int kArcSamples = 96;         // positions sampled for an arc trail
constexpr int kTopSearchSamples = 400;  // coarse look for the top of a swing, then bisection

double radiusOf(const scene::BodyDesc& body) {
  return body.shape == "disk" ? body.size_m : 0.5 * body.size_m;
}

// Angle of `position` about `pivot` from straight down, counter-clockwise positive.
double angleAbout(const core::Vec2& position, const core::Vec2& pivot) {
  return std::atan2(position.x() - pivot.x(), pivot.y() - position.y());
}

// Bars: pivots at one height share one, reaching a body radius past the outermost pivots.
void addSupports(frame::PanelModel& panel, const scene::SceneDesc& scene, const core::Vec2& shift) {
  std::map<double, std::pair<core::Vec2, core::Vec2>> bars;  // height -> (low x end, high x end)
  for (const scene::BodyDesc& body : scene.bodies) {
    if (!body.pivot_m) continue;
    const core::Vec2 p = *body.pivot_m - shift;
    const double reach = std::max(radiusOf(body), 0.02);
    auto [it, fresh] =
        bars.try_emplace(p.y(), p - core::Vec2{reach, 0.0}, p + core::Vec2{reach, 0.0});
    if (!fresh) {
      it->second.first.x() = std::min(it->second.first.x(), p.x() - reach);
      it->second.second.x() = std::max(it->second.second.x(), p.x() + reach);
    }
  }
  for (const auto& [height, ends] : bars)
    panel.suspension.supports.push_back({ends.first, ends.second});
}

// The top of the swing after a catch at t_hit: the first time the host stops rising.
std::optional<double> topOfSwing(const physics::Timeline& timeline, int host, double t_hit) {
  const double end = timeline.simulatedUntil_s();
  if (!(end > t_hit)) return std::nullopt;
  const auto rising = [&](double t) {
    return timeline.sample(t).bodies[host].velocity_mps.y() > 0.0;
  };
  double lo = t_hit;
  for (int k = 1; k <= kTopSearchSamples; ++k) {
    const double t = t_hit + (end - t_hit) * k / kTopSearchSamples;
    if (rising(t)) {
      lo = t;
      continue;
    }
    if (lo == t_hit && !rising(t_hit + 1e-9)) return std::nullopt;  // never rose
    double hi = t;
    for (int i = 0; i < 60 && hi - lo > 1e-12; ++i) {
      const double mid = 0.5 * (lo + hi);
      (rising(mid) ? lo : hi) = mid;
    }
    return hi;
  }
  return std::nullopt;
}

// The ballistic pendulum's measurement: a free body caught by a hanging one rises with it by h;
// (m + M) / m sqrt(2 g h) gives back the speed it came in with.
void addRise(frame::PanelModel& panel, const scene::SceneDesc& scene,
             const physics::Timeline& timeline, const FramePlan& plan, double t_s) {
  const std::vector<physics::BodyDef>& defs = timeline.world().bodies;
  const double g = -timeline.world().gravity_mps2.y();
  for (const physics::CollisionEvent& event : timeline.collisions()) {
    if (event.time_s > t_s) break;
    if (!event.merged || event.hitsWall()) continue;
    const bool a_hangs = defs[event.body_a].on_string, b_hangs = defs[event.body_b].on_string;
    if (a_hangs == b_hangs) continue;
    const int host = a_hangs ? event.body_a : event.body_b;
    const int guest = a_hangs ? event.body_b : event.body_a;
    const std::optional<double> top = topOfSwing(timeline, host, event.time_s);
    if (!top || t_s < *top) return;
    const core::Vec2 shift_hit = event.time_s * plan.frame_velocity_mps;
    const core::Vec2 low = timeline.sample(event.time_s).bodies[host].position_m - shift_hit;
    const core::Vec2 high =
        timeline.sample(*top).bodies[host].position_m - *top * plan.frame_velocity_mps;
    const double h = high.y() - low.y();
    const double m = defs[guest].mass_kg, M = defs[host].mass_kg;
    const double recovered = (m + M) / m * std::sqrt(2.0 * g * std::max(h, 0.0));
    const core::Vec2 came_in =
        guest == event.body_a ? event.velocity_a_before_mps : event.velocity_b_before_mps;
    frame::DimensionModel dim;
    dim.from_m = low;
    dim.to_m = high;
    dim.line_at_m = high.x() + 1.6 * radiusOf(scene.bodies[host]);
    // TRANSLATORS: h is the height the hanging block rises to at the top of its swing.
    dim.label = text::fill(text::tr("rise h = {height}"), {{"height", text::formatValue(h, "m")}});
    // The formula names the masses as the picture's labels do (m₁ + m₂ = 1.01 kg).
    const std::string mass = text::symbol(text::Symbol::kMass);
    const std::string speed_note =
        // TRANSLATORS: the speed worked out from the rise h; keep the formula as it is:
        // {m_first} and {m_second} are the two masses, {m_caught} the caught one (e.g. m₁, m₂, m₂).
        text::tr("speed from h: ({m_first} + {m_second})/{m_caught} · √(2gh) = {speed}");
    dim.notes.push_back(
        text::fill(speed_note, {{"m_first", mass + subscript(std::min(guest, host) + 1)},
                                {"m_second", mass + subscript(std::max(guest, host) + 1)},
                                {"m_caught", mass + subscript(guest + 1)},
                                {"speed", text::formatValue(recovered, "m/s")}}));
    // TRANSLATORS: {body} is the name of the body that was caught, e.g. "bullet".
    dim.notes.push_back(text::fill(
        text::tr("true speed ({body}): {speed}"),
        {{"body", scene.bodies[guest].name}, {"speed", text::formatValue(came_in.norm(), "m/s")}}));
    // The notes in the scene's top-left corner, clear of the swing (the bullet came from the
    // left, below the pivots).
    const core::Vec2 size = plan.view.max_m - plan.view.min_m;
    dim.notes_m = {plan.view.min_m.x() + 0.02 * size.x(), plan.view.max_m.y() - 0.3 * size.y()};
    panel.dimensions.push_back(dim);
    return;
  }
}

}  // namespace

void addSuspension(frame::PanelModel& panel, const scene::SceneDesc& scene,
                   const physics::Timeline& timeline, const FramePlan& plan, double t_s) {
  bool any = false;
  for (const scene::BodyDesc& body : scene.bodies) any = any || body.pivot_m.has_value();
  if (!any) return;
  const core::Vec2 shift = t_s * plan.frame_velocity_mps;
  addSupports(panel, scene, shift);
  for (std::size_t i = 0; i < scene.bodies.size() && i < panel.bodies.size(); ++i) {
    if (!scene.bodies[i].pivot_m) continue;
    panel.suspension.strings.push_back(
        {*scene.bodies[i].pivot_m - shift, panel.bodies[i].center_m});
  }
  if (scene.view.arc_trail && t_s > 0.0) {
    for (std::size_t i = 0; i < scene.bodies.size() && i < panel.bodies.size(); ++i) {
      if (!scene.bodies[i].pivot_m) continue;
      const core::Vec2 pivot = *scene.bodies[i].pivot_m;
      double lowest = angleAbout(timeline.sample(0.0).bodies[i].position_m, pivot);
      double highest = lowest;
      for (int k = 1; k <= kArcSamples; ++k) {
        const double a =
            angleAbout(timeline.sample(t_s * k / kArcSamples).bodies[i].position_m, pivot);
        lowest = std::min(lowest, a);
        highest = std::max(highest, a);
      }
      if (highest - lowest < 1e-3) continue;
      const double radius = (panel.bodies[i].center_m - (pivot - shift)).norm();
      panel.suspension.arcs.push_back(
          {pivot - shift, radius, lowest, highest, panel.bodies[i].fill});
    }
  }
  addRise(panel, scene, timeline, plan, t_s);
}

void includePivots(const scene::SceneDesc& scene, core::Vec2& low, core::Vec2& high) {
  for (const scene::BodyDesc& body : scene.bodies) {
    if (!body.pivot_m) continue;
    const double reach = std::max(radiusOf(body), 0.02);
    low = low.cwiseMin(*body.pivot_m - core::Vec2{reach, reach});
    high = high.cwiseMax(*body.pivot_m + core::Vec2{reach, reach});
  }
}

}  // namespace collide::compose
