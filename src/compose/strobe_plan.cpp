#include "compose/strobe_plan.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collide::compose {
namespace {

constexpr double kStrobeFirstAlpha = 0.18;  // opacity of the earliest strobe image
constexpr double kStrobeRates_hz[] = {50.0, 40.0, 25.0, 20.0, 10.0, 8.0,  5.0,
                                      4.0,  2.5,  2.0,  1.0,  0.5,  0.25, 0.1};

// Two images of one body in one place (it has not moved between them).
bool samePlace(const frame::BodyModel& a, const frame::BodyModel& b) {
  const core::Vec2 size = a.half_extent_m + b.half_extent_m;
  return (b.center_m - a.center_m).norm() <= 1e-6 * size.norm();
}

// Two images of one body overlap, unless it has not moved (they stack into one image).
bool imagesOverlapMoving(const frame::BodyModel& a, const frame::BodyModel& b) {
  return !samePlace(a, b) && strobeImagesOverlap(a, b);
}

// Bodies stuck together at time t_s (bonds formed up to then): a group number per body.
std::vector<std::size_t> stuckGroups(const FramePlan& plan, std::size_t bodies, double t_s) {
  std::vector<std::size_t> group(bodies);
  for (std::size_t i = 0; i < bodies; ++i) group[i] = i;
  const auto root = [&](std::size_t i) {
    while (group[i] != i) i = group[i] = group[group[i]];
    return i;
  };
  for (const FramePlan::Bond& bond : plan.bonds) {
    if (bond.time_s > t_s) break;
    const auto a = static_cast<std::size_t>(bond.body_a), b = static_cast<std::size_t>(bond.body_b);
    if (a < bodies && b < bodies) group[root(a)] = root(b);
  }
  for (std::size_t i = 0; i < bodies; ++i) group[i] = root(i);
  return group;
}

std::vector<frame::BodyModel> imagesAt(const StrobeSubject& panel, double t_s) {
  return bodyImages(panel.scene, panel.timeline, panel.plan, panel.theme, t_s);
}

// The bodies a panel photographs, in order.
std::vector<std::size_t> strobedBodies(const StrobeSubject& panel, std::size_t bodies) {
  std::vector<std::size_t> out;
  if (panel.strobed) {
    for (std::size_t i : *panel.strobed) {
      if (i < bodies) out.push_back(i);
    }
    return out;
  }
  for (std::size_t i = 0; i < bodies; ++i) out.push_back(i);
  return out;
}

// The photographed bodies that move but whose strobe at rate_hz (keep_apart) shows no image of
// them anywhere but where they started and where they end: nothing of how they moved.
int motionsUnshown(const StrobeSubject& panel, double duration_s, double rate_hz) {
  const std::vector<frame::BodyModel> start = imagesAt(panel, 0.0);
  const std::vector<frame::BodyModel> last = imagesAt(panel, duration_s);
  const StrobeImages picture = strobeGhosts(panel, duration_s, rate_hz, last, true);
  int unshown = 0;
  for (std::size_t i : strobedBodies(panel, last.size())) {
    if (samePlace(start[i], last[i])) continue;
    bool shown = false;
    for (std::size_t g = 0; g < picture.ghosts.size() && !shown; ++g) {
      shown = picture.ghost_bodies[g] == i && !samePlace(picture.ghosts[g], start[i]) &&
              !samePlace(picture.ghosts[g], last[i]);
    }
    if (!shown) ++unshown;
  }
  return unshown;
}

}  // namespace

int strobeImageCount(double duration_s, double rate_hz) {
  return static_cast<int>(std::floor(duration_s * rate_hz + 1e-9)) + 1;
}

double chooseStrobeRate_hz(const std::vector<StrobeSubject>& panels, double duration_s,
                           int max_images) {
  const auto apart = [&](double rate_hz) {
    for (const StrobeSubject& panel : panels) {
      std::vector<frame::BodyModel> last = imagesAt(panel, 0.0);
      for (int k = 1; k < strobeImageCount(duration_s, rate_hz); ++k) {
        std::vector<frame::BodyModel> next = imagesAt(panel, k / rate_hz);
        for (std::size_t i : strobedBodies(panel, next.size())) {
          if (imagesOverlapMoving(last[i], next[i])) return false;
        }
        last = std::move(next);
      }
    }
    return true;
  };
  std::vector<double> enough;  // the rates that give kMinStrobeImages to max_images, fastest first
  for (double rate : kStrobeRates_hz) {
    const int images = strobeImageCount(duration_s, rate);
    if (images > std::min(max_images, kMaxStrobeImages)) continue;
    if (images < kMinStrobeImages) break;
    enough.push_back(rate);
    if (apart(rate)) return rate;
  }
  if (enough.empty()) return kStrobeRates_hz[0];
  // No rate keeps every body's next image clear (a body starting from rest or coming to rest),
  // so the picture leaves out the images that would overlap, and at one rate that may leave a
  // body nothing between where it started and where it ends where another rate's flashes fall
  // clear (newtons-cradle at 8 per second: balls 1 and 5 showed no image of their swings; at 25
  // one each, at the middle of each swing). The slowest rate that leaves the fewest such bodies.
  double best_hz = enough.back();
  int fewest = std::numeric_limits<int>::max();
  for (auto rate = enough.rbegin(); rate != enough.rend() && fewest > 0; ++rate) {
    int unshown = 0;
    for (const StrobeSubject& panel : panels) unshown += motionsUnshown(panel, duration_s, *rate);
    if (unshown < fewest) {
      fewest = unshown;
      best_hz = *rate;
    }
  }
  return best_hz;
}

bool strobeImagesOverlap(const frame::BodyModel& a, const frame::BodyModel& b) {
  const core::Vec2 d = (b.center_m - a.center_m).cwiseAbs();
  const core::Vec2 size = a.half_extent_m + b.half_extent_m;
  if (a.shape == frame::BodyShape::kDisk && b.shape == frame::BodyShape::kDisk) {
    return d.norm() < size.x() * (1.0 - 1e-9);
  }
  return d.x() < size.x() * (1.0 - 1e-9) && d.y() < size.y() * (1.0 - 1e-9);
}

std::vector<const physics::CollisionEvent*> strobeImpacts(const physics::Timeline& timeline,
                                                          double duration_s) {
  std::vector<const physics::CollisionEvent*> between_bodies, with_walls;
  for (const physics::CollisionEvent& event : timeline.collisions()) {
    if (event.time_s <= 0.0 || event.time_s >= duration_s) continue;
    std::vector<const physics::CollisionEvent*>& kind =
        event.hitsWall() ? with_walls : between_bodies;
    if (kind.size() < kMaxStrobeImpacts) kind.push_back(&event);
    if (between_bodies.size() >= kMaxStrobeImpacts) break;
  }
  return between_bodies.empty() ? with_walls : between_bodies;
}

StrobeImages strobeGhosts(const StrobeSubject& panel, double duration_s, double rate_hz,
                          const std::vector<frame::BodyModel>& last, bool keep_apart) {
  const int images = std::min(kMaxStrobeImages, strobeImageCount(duration_s, rate_hz));
  const auto alpha = [&](double flashes_in) {
    return static_cast<float>(kStrobeFirstAlpha +
                              (1.0 - kStrobeFirstAlpha) * flashes_in / std::max(1, images - 1));
  };
  StrobeImages out;
  const std::vector<std::size_t> strobed = strobedBodies(panel, last.size());
  if (!keep_apart) {
    for (int k = 0; k + 1 < images; ++k) {
      std::vector<frame::BodyModel> now = imagesAt(panel, k / rate_hz);
      for (std::size_t i : strobed) {
        if (i >= now.size()) continue;
        now[i].fill.a *= alpha(k);
        out.ghosts.push_back(now[i]);
        out.ghost_bodies.push_back(i);
      }
    }
    return out;
  }
  // The last image of every body (the solid body, `last`) is always drawn. Next comes the first
  // collision strobeImpacts pictures, at its instant (the collision itself, which the flashes
  // rarely catch and the picture is about), then every body's first image (where it started), kept
  // over a last image but not over the collision's, then the later collisions, then the flashes
  // between. Each gives way in turn: a stuck group keeps its image only where every member clears
  // every image already kept, of any body, from another instant (images of one instant may touch
  // or press into each other: they are the contact itself). So nothing is drawn over a trail,
  // joined bodies are spaced as one, and no body's image lies on another body's earlier or last
  // one.
  struct Kept {
    double t_s;  // when the image was taken; the last image: duration_s
    std::size_t body;
    frame::BodyModel image;
  };
  std::vector<Kept> kept;
  for (std::size_t i : strobed) kept.push_back({duration_s, i, last[i]});
  const std::size_t last_count = kept.size();
  // Offers the images at t_s of the bodies in `offered` (each with its stuck partners); returns
  // whether any was kept. over_last: keep them whatever last image they overlap (the first
  // images). together: the offered bodies are kept or left out as one (the two partners of a
  // collision).
  const std::vector<frame::BodyModel> start = imagesAt(panel, 0.0);
  const auto offer = [&](double t_s, const std::vector<bool>& offered, float alpha_now,
                         bool over_last, bool together) {
    std::vector<frame::BodyModel> now = imagesAt(panel, t_s);
    const std::size_t bodies = std::min(now.size(), last.size());
    std::vector<std::size_t> group = stuckGroups(panel.plan, bodies, t_s);
    std::vector<bool> in_group(bodies, false);
    std::size_t first_offered = bodies;
    for (std::size_t i = 0; i < bodies; ++i) {
      if (i >= offered.size() || !offered[i]) continue;
      in_group[group[i]] = true;
      first_offered = std::min(first_offered, group[i]);
    }
    if (together) {
      for (std::size_t& g : group) {
        if (in_group[g]) g = first_offered;
      }
      in_group[first_offered] = first_offered < bodies;
    }
    // Where each body is now: a kept image of another body that stands where that body is now
    // is also its image of this instant (a body at rest until it is hit).
    const auto ofThisInstant = [&](const Kept& other) {
      return other.t_s == t_s || (other.body < bodies && samePlace(other.image, now[other.body]));
    };
    // An image where the body started (at rest until now) is its first image too, drawn over a
    // last image like any first image.
    const auto firstToo = [&](std::size_t i) {
      return over_last || (i < start.size() && samePlace(now[i], start[i]));
    };
    // clear: the image may be drawn; stacked: it lies exactly on an image of its own body already
    // kept (a body at rest), so leaving it out leaves nothing out.
    std::vector<bool> clear(bodies, true), stacked(bodies, false), shown(bodies, false);
    for (std::size_t i : strobed) {
      if (i >= bodies || !in_group[group[i]]) continue;
      shown[i] = true;
      for (Kept& other : kept) {
        if (other.body == i && samePlace(now[i], other.image)) {
          stacked[i] = true;
          clear[i] = false;
          // A body at rest from t_s until a later image kept of it (hit where it stood): that
          // image is dated, and as faint as, the earlier instant, like the start of a trail.
          if (t_s < other.t_s && other.t_s < duration_s) {
            const float fill_a = now[i].fill.a * alpha_now;
            other.t_s = t_s;
            other.image.fill.a = fill_a;
          }
        } else if (!(firstToo(i) && other.t_s == duration_s) && !ofThisInstant(other) &&
                   strobeImagesOverlap(now[i], other.image)) {
          clear[i] = false;
        }
      }
    }
    // A member stacked on its own image (a body at rest until the instant it is hit and joined)
    // adds nothing and hides nothing, so it does not hold its partners back.
    std::vector<bool> group_clear(bodies, true);
    for (std::size_t i = 0; i < bodies; ++i)
      group_clear[group[i]] = group_clear[group[i]] && (clear[i] || stacked[i]);
    bool any = false;
    for (std::size_t i = 0; i < bodies; ++i) {
      if (!shown[i]) continue;
      if (stacked[i]) continue;
      if (!group_clear[group[i]]) {
        out.moving_left_out = true;
        continue;
      }
      now[i].fill.a *= alpha_now;
      // Numbered like its body (a crowded scene's tag), so an image is told from its neighbours
      // by more than a faint colour; a gas's marked molecules are told by their colours. Not
      // where a solid last image lies over part of it (a first image may): the painter writes
      // numbers over all shapes, and half a number would stand on that body beside its own. Nor
      // where one body is photographed: every image is of it, so a number on each tells nothing
      // (bouncing-ball in print: "1" on every image, crowding a bounce's against the next flash's).
      bool under_last = false;
      for (std::size_t k = 0; k < last_count; ++k)
        under_last = under_last || strobeImagesOverlap(now[i], kept[k].image);
      if (!panel.strobed && strobed.size() > 1 && !under_last) now[i].tag = last[i].tag;
      kept.push_back({t_s, i, std::move(now[i])});
      any = true;
    }
    return any;
  };
  const std::vector<bool> every(last.size(), true);
  // The collisions pictured at their instants (a gas's marked molecules are photographed along
  // their paths instead).
  const std::vector<const physics::CollisionEvent*> impacts =
      panel.strobed ? std::vector<const physics::CollisionEvent*>{}
                    : strobeImpacts(panel.timeline, duration_s);
  const auto offerImpact = [&](const physics::CollisionEvent& event) {
    std::vector<bool> pair(last.size(), false);
    for (const int body : {event.body_a, event.body_b}) {
      if (body >= 0 && static_cast<std::size_t>(body) < pair.size())
        pair[static_cast<std::size_t>(body)] = true;
    }
    // As faint as a flash at that instant would be. One that gives way leaves out no flash: the
    // caption counts the collision images drawn, not those that might have been.
    const bool flash_left_out = out.moving_left_out;
    if (offer(event.time_s, pair, alpha(event.time_s * rate_hz), false, true)) ++out.impacts_shown;
    out.moving_left_out = flash_left_out;
  };
  // Bounces on a wall recur at every arc: after the first, each gives way to the flashes, whose
  // equal steps draw the arcs (a flash left out for every bounce would break each parabola).
  const bool bounces = !impacts.empty() && impacts.front()->hitsWall();
  const auto offerLaterImpacts = [&] {
    for (std::size_t n = 1; n < impacts.size(); ++n) offerImpact(*impacts[n]);
  };
  if (!impacts.empty()) offerImpact(*impacts.front());
  offer(0.0, every, alpha(0), true, false);
  if (!bounces) offerLaterImpacts();
  for (int k = 1; k + 1 < images; ++k) offer(k / rate_hz, every, alpha(k), false, false);
  if (bounces) offerLaterImpacts();
  kept.erase(kept.begin(), kept.begin() + static_cast<std::ptrdiff_t>(last_count));
  // Drawn in time order, so a later image lies over an earlier one it touches.
  std::stable_sort(kept.begin(), kept.end(),
                   [](const Kept& a, const Kept& b) { return a.t_s < b.t_s; });
  for (Kept& image : kept) {
    out.ghosts.push_back(std::move(image.image));
    out.ghost_bodies.push_back(image.body);
  }
  return out;
}

}  // namespace collide::compose
