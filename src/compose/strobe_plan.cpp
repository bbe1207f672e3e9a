#include "compose/strobe_plan.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "compose/frame_geometry.hpp"
#include "compose/readouts.hpp"

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

// Gives each glider's image among `images` (every body's, at t_s) its bumpers, squeezed as its
// solid body's are at that instant: a faint glider is drawn as a glider, not a plain block.
void addImageBumpers(const StrobeSubject& panel, double t_s,
                     std::vector<frame::BodyModel>& images) {
  bool gliders = false;
  for (const scene::BodyDesc& body : panel.scene.bodies) gliders = gliders || isGlider(body);
  if (!gliders) return;
  frame::PanelModel at;
  at.bodies = images;
  // Only the side a wall faces decides which bumper it squeezes.
  for (const scene::WallDesc& wall : scene::allWalls(panel.scene))
    at.walls.push_back({wall.position_m, wall.normal.normalized()});
  const physics::EnergyBooks books = panelBooks(panel.timeline, panel.plan, t_s);
  for (std::size_t i = 0; i < images.size(); ++i)
    images[i].bumpers = gliderBumpers(panel.scene, books, at, i);
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

// The opacity of an image `flashes_in` flashes after the first, of `images` in all.
float strobeAlpha(double flashes_in, int images) {
  return static_cast<float>(kStrobeFirstAlpha +
                            (1.0 - kStrobeFirstAlpha) * flashes_in / std::max(1, images - 1));
}

// Without keep_apart (the user set the rate): every flash shows every body, overlapping or not.
StrobeImages everyFlash(const StrobeSubject& panel, double duration_s, double rate_hz,
                        const std::vector<frame::BodyModel>& last) {
  const int images = std::min(kMaxStrobeImages, strobeImageCount(duration_s, rate_hz));
  StrobeImages out;
  const std::vector<std::size_t> strobed = strobedBodies(panel, last.size());
  for (int k = 0; k + 1 < images; ++k) {
    std::vector<frame::BodyModel> now = imagesAt(panel, k / rate_hz);
    addImageBumpers(panel, k / rate_hz, now);
    for (std::size_t i : strobed) {
      if (i >= now.size()) continue;
      now[i].fill.a *= strobeAlpha(k, images);
      out.ghosts.push_back(now[i]);
      out.ghost_bodies.push_back(i);
    }
  }
  return out;
}

// The images a strobe keeps apart (keep_apart): the last image of every body (the solid body,
// `last`) is always drawn. Next comes the first collision strobeImpacts pictures, at its instant
// (the collision itself, which the flashes rarely catch and the picture is about), then every
// body's first image (where it started), kept over a last image and beside its own body's image
// at the collision, but not over the other body's there,
// then the later collisions, then the flashes between. Each gives way in turn: a stuck group
// keeps its image only where every member clears every image already kept, of any body, from
// another instant (images of one instant may touch or press into each other: they are the
// contact itself). So nothing is drawn over a trail, joined bodies are spaced as one, and no
// body's image lies on another body's earlier or last one.
class StrobeKeeper {
 public:
  StrobeKeeper(const StrobeSubject& panel, double duration_s, double rate_hz,
               const std::vector<frame::BodyModel>& last)
      : panel_(panel),
        duration_s_(duration_s),
        rate_hz_(rate_hz),
        last_(last),
        images_(std::min(kMaxStrobeImages, strobeImageCount(duration_s, rate_hz))),
        strobed_(strobedBodies(panel, last.size())) {
    for (std::size_t i : strobed_) kept_.push_back({duration_s, i, last[i]});
    last_count_ = kept_.size();
    start_ = imagesAt(panel, 0.0);
  }

  StrobeImages keepApart() {
    const std::vector<bool> every(last_.size(), true);
    // The collisions pictured at their instants (a gas's marked molecules are photographed along
    // their paths instead).
    const std::vector<const physics::CollisionEvent*> impacts =
        panel_.strobed ? std::vector<const physics::CollisionEvent*>{}
                       : strobeImpacts(panel_.timeline, duration_s_);
    // Bounces on a wall recur at every arc: after the first, each gives way to the flashes, whose
    // equal steps draw the arcs (a flash left out for every bounce would break each parabola).
    const bool bounces = !impacts.empty() && impacts.front()->hitsWall();
    if (!impacts.empty()) offerImpact(*impacts.front());
    offer(0.0, every, alpha(0), true, false);
    if (!bounces) offerLaterImpacts(impacts);
    for (int k = 1; k + 1 < images_; ++k) offer(k / rate_hz_, every, alpha(k), false, false);
    if (bounces) offerLaterImpacts(impacts);
    return inTimeOrder();
  }

 private:
  struct Kept {
    double t_s;  // when the image was taken; the last image: duration_s
    std::size_t body;
    frame::BodyModel image;
  };
  // What an offer of the images at one instant decides per body. clear: the image may be drawn;
  // stacked: it lies exactly on an image of its own body already kept (a body at rest), so
  // leaving it out leaves nothing out; shown: it was offered.
  // over: it lies on a last (solid) image, which would hide it: drawn over the bodies.
  struct Judged {
    std::vector<bool> clear, stacked, shown, over;
  };

  float alpha(double flashes_in) const { return strobeAlpha(flashes_in, images_); }

  // The stuck groups at t_s (a group number per body) and which of them are offered
  // (`in_group`, per group number): every group with an offered body; `together`: the offered
  // bodies as one group.
  std::vector<std::size_t> offeredGroups(double t_s, std::size_t bodies,
                                         const std::vector<bool>& offered, bool together,
                                         std::vector<bool>& in_group) const {
    std::vector<std::size_t> group = stuckGroups(panel_.plan, bodies, t_s);
    in_group.assign(bodies, false);
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
    return group;
  }

  // Whether each offered image at t_s (`now`) is clear of the images kept, or stacked on its own
  // body's. over_last: keep them whatever last image they overlap (the first images).
  Judged judge(double t_s, const std::vector<frame::BodyModel>& now,
               const std::vector<std::size_t>& group, const std::vector<bool>& in_group,
               float alpha_now, bool over_last) {
    const std::size_t bodies = group.size();
    // Where each body is now: a kept image of another body that stands where that body is now
    // is also its image of this instant (a body at rest until it is hit).
    const auto ofThisInstant = [&](const Kept& other) {
      return other.t_s == t_s || (other.body < bodies && samePlace(other.image, now[other.body]));
    };
    // An image where the body started (at rest until now) is its first image too, drawn over a
    // last image like any first image.
    const auto firstToo = [&](std::size_t i) {
      return over_last || (i < start_.size() && samePlace(now[i], start_[i]));
    };
    Judged judged{std::vector<bool>(bodies, true), std::vector<bool>(bodies, false),
                  std::vector<bool>(bodies, false), std::vector<bool>(bodies, false)};
    for (std::size_t i : strobed_) {
      if (i >= bodies || !in_group[group[i]]) continue;
      judged.shown[i] = true;
      for (Kept& other : kept_) {
        if (other.body == i && samePlace(now[i], other.image)) {
          judged.stacked[i] = true;
          judged.clear[i] = false;
          // A body at rest from t_s until a later image kept of it (hit where it stood): that
          // image is dated, and as faint as, the earlier instant, like the start of a trail.
          if (t_s < other.t_s && other.t_s < duration_s_) {
            const float fill_a = now[i].fill.a * alpha_now;
            other.t_s = t_s;
            other.image.fill.a = fill_a;
          }
        } else if (over_last && other.body == i && other.t_s < duration_s_) {
          // A first image beside its own body's image at a collision (hit less than its width
          // from where it started, soft-contact's cart 2): both are kept, where it started and
          // where it was hit, the later drawn over the earlier.
          continue;
        } else if (!ofThisInstant(other) && strobeImagesOverlap(now[i], other.image)) {
          // Under a last image: a first image, or another body's image at its equal time step
          // (heavy-light's light cart under the heavy one at 3 s), is kept and drawn over the
          // bodies rather than hidden or left out; anything else overlapping gives way.
          const bool under_last = other.t_s == duration_s_ && (firstToo(i) || other.body != i);
          if (under_last) {
            judged.over[i] = true;
          } else {
            judged.clear[i] = false;
          }
        }
      }
    }
    return judged;
  }

  // Keeps the image of body i at t_s, as faint as alpha_now. Numbered like its body (a crowded
  // scene's tag), so an image is told from its neighbours by more than a faint colour; a gas's
  // marked molecules are told by their colours. An image a solid last image lies over is drawn
  // over the bodies (over_bodies) and the painter writes its number above it, not inside, where
  // half a number would stand on that body beside its own; one under a last image otherwise
  // carries none. Nor where one body is photographed: every image is of it, so a number on each
  // tells nothing (bouncing-ball in print: "1" on every image, crowding a bounce's against the
  // next flash's).
  void keep(double t_s, std::size_t i, frame::BodyModel image, float alpha_now) {
    image.fill.a *= alpha_now;
    bool under_last = false;
    for (std::size_t k = 0; k < last_count_; ++k)
      under_last = under_last || strobeImagesOverlap(image, kept_[k].image);
    if (!panel_.strobed && strobed_.size() > 1 && (!under_last || image.over_bodies))
      image.tag = last_[i].tag;
    kept_.push_back({t_s, i, std::move(image)});
  }

  // Offers the images at t_s of the bodies in `offered` (each with its stuck partners); returns
  // whether any was kept. over_last: keep them whatever last image they overlap (the first
  // images). together: the offered bodies are kept or left out as one (the two partners of a
  // collision).
  bool offer(double t_s, const std::vector<bool>& offered, float alpha_now, bool over_last,
             bool together) {
    std::vector<frame::BodyModel> now = imagesAt(panel_, t_s);
    addImageBumpers(panel_, t_s, now);
    const std::size_t bodies = std::min(now.size(), last_.size());
    std::vector<bool> in_group;
    const std::vector<std::size_t> group = offeredGroups(t_s, bodies, offered, together, in_group);
    const Judged judged = judge(t_s, now, group, in_group, alpha_now, over_last);
    // A member stacked on its own image (a body at rest until the instant it is hit and joined)
    // adds nothing and hides nothing, so it does not hold its partners back.
    std::vector<bool> group_clear(bodies, true);
    for (std::size_t i = 0; i < bodies; ++i)
      group_clear[group[i]] = group_clear[group[i]] && (judged.clear[i] || judged.stacked[i]);
    bool any = false;
    for (std::size_t i = 0; i < bodies; ++i) {
      if (!judged.shown[i]) continue;
      if (judged.stacked[i]) continue;
      if (!group_clear[group[i]]) {
        out_.moving_left_out = true;
        continue;
      }
      now[i].over_bodies = judged.over[i];
      keep(t_s, i, std::move(now[i]), alpha_now);
      any = true;
    }
    return any;
  }

  void offerImpact(const physics::CollisionEvent& event) {
    std::vector<bool> pair(last_.size(), false);
    for (const int body : {event.body_a, event.body_b}) {
      if (body >= 0 && static_cast<std::size_t>(body) < pair.size())
        pair[static_cast<std::size_t>(body)] = true;
    }
    // As faint as a flash at that instant would be. One that gives way leaves out no flash: the
    // caption counts the collision images drawn, not those that might have been.
    const bool flash_left_out = out_.moving_left_out;
    if (offer(event.time_s, pair, alpha(event.time_s * rate_hz_), false, true)) {
      ++(event.release ? out_.releases_shown : out_.impacts_shown);
    }
    out_.moving_left_out = flash_left_out;
  }

  void offerLaterImpacts(const std::vector<const physics::CollisionEvent*>& impacts) {
    for (std::size_t n = 1; n < impacts.size(); ++n) offerImpact(*impacts[n]);
  }

  // The images kept but the last ones, drawn in time order, so a later image lies over an
  // earlier one it touches.
  StrobeImages inTimeOrder() {
    kept_.erase(kept_.begin(), kept_.begin() + static_cast<std::ptrdiff_t>(last_count_));
    std::stable_sort(kept_.begin(), kept_.end(),
                     [](const Kept& a, const Kept& b) { return a.t_s < b.t_s; });
    for (Kept& image : kept_) {
      out_.ghosts.push_back(std::move(image.image));
      out_.ghost_bodies.push_back(image.body);
    }
    return std::move(out_);
  }

  const StrobeSubject& panel_;
  const double duration_s_, rate_hz_;
  const std::vector<frame::BodyModel>& last_;
  const int images_;
  const std::vector<std::size_t> strobed_;
  std::vector<Kept> kept_;
  std::size_t last_count_ = 0;
  std::vector<frame::BodyModel> start_;
  StrobeImages out_;
};

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
  if (!keep_apart) return everyFlash(panel, duration_s, rate_hz, last);
  return StrobeKeeper(panel, duration_s, rate_hz, last).keepApart();
}

}  // namespace collide::compose
