// SPDX-License-Identifier: MIT
// Strobe pictures that read like a photograph pasted into notes, checked on the frame description
// (no pixels read): in every preset's strobe at the rate the picture chooses, no two images taken
// at different instants overlap, of one body or of two (a joined pair is spaced as one, a body's
// images never lie on its partner's), images of one instant excepted (a contact); every body
// that moves shows its first image, where it started, which with the last, solid one is always
// drawn (unless it would overlap the first collision's images); the first collision between two
// bodies (where there is none, with a wall: a ball's bounce) is pictured at its instant, whatever
// else gives way; a picture that ends before the run does so where every body turns at once. A rate
// the user gives (--rate) draws every flash of the whole run, and then images do overlap somewhere:
// the check has teeth. Each image is matched to its body and instant (a flash, or a collision of
// that body) from the Timeline (strobe_images.cpp), independently of compose.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "app/animation.hpp"
#include "frame/layout.hpp"
#include "scene/scene_desc.hpp"
#include "strobe_images.hpp"

namespace collide {
namespace {

using strobe_images::bodiesOf;
using strobe_images::drawnAt;
using strobe_images::halfSize;
using strobe_images::Image;
using strobe_images::imagesByBody;
using strobe_images::kFewBodies;
using strobe_images::kImpact;
using strobe_images::kLast;
using strobe_images::overlap;
using strobe_images::picturedCollisions;

// Whether image b of body j is also body j's image at the instant image a was taken: taken then,
// or standing where body j was then (a body at rest until it is hit).
bool ofInstantOf(const scene::SceneDesc& scene, const physics::Timeline& timeline, const Image& a,
                 std::size_t j, const Image& b) {
  if (a.t_s == b.t_s) return true;
  const core::Vec2 then = drawnAt(scene, timeline, j, a.t_s);
  return (b.center - then).norm() <= 1e-9 * (1.0 + then.norm());
}

// The overlapping pairs of images taken at different instants, of one body or of two, described;
// none: empty. Images of one instant may touch or press together (that is a contact). A body's
// first image and any last image are both always drawn (where it started, where all ended), so
// they may overlap; so may a body's first image and its own image at a collision (where it
// started and where it was hit, both always drawn: soft-contact's cart 2 starts less than its
// width from where it is hit).
std::vector<std::string> overlaps(const scene::SceneDesc& scene, const physics::Timeline& timeline,
                                  const std::vector<std::vector<Image>>& images) {
  std::vector<std::pair<std::size_t, const Image*>> all;
  for (std::size_t i = 0; i < images.size(); ++i) {
    for (const Image& image : images[i]) all.emplace_back(i, &image);
  }
  std::vector<std::string> found;
  for (std::size_t a = 0; a < all.size(); ++a) {
    for (std::size_t b = a + 1; b < all.size(); ++b) {
      const Image &x = *all[a].second, &y = *all[b].second;
      if ((x.flash == 0 && y.flash == kLast) || (x.flash == kLast && y.flash == 0)) continue;
      const bool one_body = all[a].first == all[b].first;
      if (one_body &&
          ((x.flash == 0 && y.flash == kImpact) || (x.flash == kImpact && y.flash == 0)))
        continue;
      // An image on a last one, drawn over the bodies: seen, not hidden (issue 37).
      if ((x.flash == kLast && y.over) || (y.flash == kLast && x.over)) continue;
      if (ofInstantOf(scene, timeline, x, all[b].first, y) ||
          ofInstantOf(scene, timeline, y, all[a].first, x))
        continue;
      if (overlap(x, y)) found.push_back(x.what + " and " + y.what);
    }
  }
  return found;
}

// The images of the bodies of the first pictured collision in (0, end_s), at its instant, from
// the simulation, each with its body; none where there is no such collision.
std::vector<std::pair<std::size_t, Image>> firstCollisionImages(const scene::SceneDesc& scene,
                                                                const physics::Timeline& timeline,
                                                                double end_s) {
  for (const physics::CollisionEvent& event : picturedCollisions(timeline, end_s)) {
    std::vector<std::pair<std::size_t, Image>> pair;
    for (const std::size_t i : bodiesOf(event)) {
      pair.emplace_back(i,
                        Image{drawnAt(scene, timeline, i, event.time_s), halfSize(scene.bodies[i]),
                              scene.bodies[i].shape == "disk", kImpact, event.time_s, ""});
    }
    return pair;
  }
  return {};
}

// Bodies whose first image is missing: every body that does not end where it started must show
// where it started (its image at t = 0), found from the simulation, even where that image
// overlaps its own image at the first collision (soft-contact's cart 2 starts less than its width
// from where it is hit: both are drawn, issue 37), unless it would overlap the other body's image
// there (the collision outranks where a body started).
std::vector<std::string> missingFirstImages(const scene::SceneDesc& scene,
                                            const physics::Timeline& timeline,
                                            const std::vector<std::vector<Image>>& images,
                                            double end_s) {
  const std::vector<std::pair<std::size_t, Image>> collision =
      firstCollisionImages(scene, timeline, end_s);
  std::vector<std::string> missing;
  for (std::size_t i = 0; i < images.size(); ++i) {
    const core::Vec2 start = drawnAt(scene, timeline, i, 0.0);
    const core::Vec2 end = drawnAt(scene, timeline, i, end_s);
    if ((end - start).norm() <= 1e-9 * (1.0 + start.norm())) continue;  // at rest: drawn once
    if (images[i].empty()) continue;  // not photographed (the rest of a gas)
    bool shown = false, gives_way = false;
    for (const Image& image : images[i]) shown = shown || image.flash == 0;
    const Image first{start, halfSize(scene.bodies[i]), scene.bodies[i].shape == "disk", 0, 0.0,
                      ""};
    for (const auto& [body, image] : collision) {
      // Not where it stood at rest until the collision (then the two are one image).
      if (body != i && (image.center - start).norm() > 1e-9 * (1.0 + start.norm()) &&
          overlap(first, image))
        gives_way = true;
    }
    if (!shown && !gives_way) missing.push_back("body " + std::to_string(i + 1));
  }
  return missing;
}

// Bodies that move but show no image other than where they started and where they end, found
// from the simulation: nothing of how they moved (newtons-cradle at 8 images per second showed
// balls 1 and 5 only where they started and where they ended). Not every picture can avoid it:
// granular-chain's blocks move less than two of their widths between neighbours' images.
std::vector<std::string> motionsUnshown(const scene::SceneDesc& scene,
                                        const physics::Timeline& timeline,
                                        const std::vector<std::vector<Image>>& images,
                                        double end_s) {
  std::vector<std::string> unshown;
  for (std::size_t i = 0; i < images.size(); ++i) {
    if (images[i].empty()) continue;  // not photographed (the rest of a gas)
    const core::Vec2 start = drawnAt(scene, timeline, i, 0.0);
    const core::Vec2 end = drawnAt(scene, timeline, i, end_s);
    const auto at = [](const Image& image, const core::Vec2& place) {
      return (image.center - place).norm() <= 1e-9 * (1.0 + place.norm());
    };
    if ((end - start).norm() <= 1e-9 * (1.0 + start.norm())) continue;  // ends where it started
    bool shown = false;
    for (const Image& image : images[i]) shown = shown || (!at(image, start) && !at(image, end));
    if (!shown) unshown.push_back("body " + std::to_string(i + 1));
  }
  return unshown;
}

// The first pictured collision (between two bodies; where there is none, of a body with a wall),
// if its bodies are not pictured where they met: each must have an image where the simulation
// puts it at that instant (an image taken then, or one of a body at rest that stands there
// anyway); empty when pictured or there is none. The collision is what the picture is about: it
// gives way to no other image.
std::string firstCollisionMissing(const scene::SceneDesc& scene, const physics::Timeline& timeline,
                                  const std::vector<std::vector<Image>>& images, double end_s) {
  for (const physics::CollisionEvent& event : picturedCollisions(timeline, end_s)) {
    std::string missing;
    for (const std::size_t i : bodiesOf(event)) {
      const core::Vec2 at = drawnAt(scene, timeline, i, event.time_s);
      bool shown = false;
      for (const Image& image : images[i])
        shown = shown || (image.center - at).norm() <= 1e-9 * (1.0 + at.norm());
      if (!shown) missing += " body " + std::to_string(i + 1);
    }
    if (missing.empty()) return {};
    return "the collision at t = " + std::to_string(event.time_s) +
           " s is not pictured:" + missing + " not drawn where it met its partner or wall";
  }
  return {};
}

TEST(StrobeSpacingTest, FirstImagesKeptAndNoImagesOverlapAtTheChosenRate) {
  int checked = 0, overlapping_at_a_given_rate = 0;
  for (const scene::PresetInfo& preset : scene::presetList()) {
    const scene::SceneDesc scene = scene::loadPreset(preset.name);
    ASSERT_FALSE(scene.view.center_of_momentum_frame) << preset.name << ": lab-frame places only";
    SCOPED_TRACE(preset.name);
    const app::Animation animation = app::animate(scene, {640, 360});
    const compose::FrameSource& source = animation.frames;
    const double rate_hz = source.strobeRate_hz();
    const frame::FrameModel chosen = source.strobeFrame(0.0);
    const frame::FrameModel every = source.strobeFrame(rate_hz, false);
    // The picture's own span: the whole run, or up to an instant where every body turns at once.
    const double end_s = source.strobeSpan_s();
    ASSERT_GT(end_s, 0.0);
    ASSERT_LE(end_s, scene.duration_s);
    ASSERT_EQ(chosen.panels.size(), source.panelCount());
    for (std::size_t p = 0; p < source.panelCount(); ++p) {
      const physics::Timeline& timeline = source.panelTimeline(p);
      if (end_s < scene.duration_s) {
        // Every body at rest there (a velocity that reverses is zero where it does; found to
        // round-off of the time, what is left is g times that), and moving again after it.
        const physics::Snapshot turn = timeline.sample(end_s);
        const physics::Snapshot later = timeline.sample(0.5 * (end_s + scene.duration_s));
        double moved_m = 0.0;
        for (std::size_t i = 0; i < turn.bodies.size(); ++i) {
          EXPECT_LE(turn.bodies[i].velocity_mps.norm(), 1e-6) << "body " << i + 1;
          moved_m =
              std::max(moved_m, (later.bodies[i].position_m - turn.bodies[i].position_m).norm());
        }
        EXPECT_GT(moved_m, 0.0) << "the span ends where everything stops for good";
      }
      const std::vector<std::vector<Image>> images = imagesByBody(
          scene, timeline, chosen.panels[p], rate_hz, end_s, scene.bodies.size() <= kFewBodies);
      const std::vector<std::string> found = overlaps(scene, timeline, images);
      EXPECT_TRUE(found.empty()) << "panel " << p + 1 << ": " << found.size()
                                 << " overlapping pairs, e.g. " << found.front();
      const std::vector<std::string> missing = missingFirstImages(scene, timeline, images, end_s);
      EXPECT_TRUE(missing.empty())
          << "panel " << p + 1 << ": no first image of " << missing.front();
      if (scene.bodies.size() <= kFewBodies) {
        EXPECT_EQ(firstCollisionMissing(scene, timeline, images, end_s), "") << "panel " << p + 1;
      }
      // A rate the user gives draws every flash of the whole run.
      if (!overlaps(scene, timeline,
                    imagesByBody(scene, timeline, every.panels[p], rate_hz, scene.duration_s))
               .empty()) {
        ++overlapping_at_a_given_rate;
      }
    }
    ++checked;
  }
  EXPECT_GE(checked, 15) << "the presets were not found";
  // Drawing every flash (a rate the user gives) overlaps in the presets that slow down or stop
  // (stick-2d, clay, car-crash, soft-contact, granular-chain, ...).
  EXPECT_GE(overlapping_at_a_given_rate, 5);
}

// A strobe of one body numbers only its last image, the one its label points to: every image is
// of that body, so a number on each would tell nothing and only crowd images that stand close
// (bouncing-ball printed 8 cm wide at 300 dpi, where the ball is small enough to be numbered: a
// bounce's "1" pressed against the next flash's).
TEST(StrobeSpacingTest, ImagesOfALoneBodyCarryNoNumber) {
  const scene::SceneDesc scene = scene::loadPreset("bouncing-ball");
  ASSERT_EQ(scene.bodies.size(), 1u);
  const int width_px = static_cast<int>(std::lround(8.0 / 2.54 * 300.0));
  const app::Animation animation =
      app::animate(scene, {width_px, width_px * 2 / 3, frame::printTextFloorPx(300.0)});
  const frame::FrameModel frame = animation.frames.strobeFrame(0.0);
  ASSERT_EQ(frame.panels.size(), 1u);
  const frame::PanelModel& panel = frame.panels.front();
  ASSERT_EQ(panel.bodies.size(), 1u);
  ASSERT_NE(panel.bodies.front().tag, "") << "at this size the ball is numbered: else no check";
  ASSERT_GE(panel.ghosts.size(), 6u);
  for (const frame::BodyModel& ghost : panel.ghosts) {
    EXPECT_EQ(ghost.tag, "") << "the image at (" << ghost.center_m.x() << ", " << ghost.center_m.y()
                             << ")";
  }
}

// A swing's strobe ends at the top of the swing after the collision, from the exact pendulum:
// a quarter period sqrt(L/g)·K(sin(θ/2)) from the bottom to an amplitude θ (docs/physics.md). Later
// images would retrace the swing back over the ones drawn. The times are derived here, as
// VisualsGLTest's goldens of the same instants derive them.
TEST(StrobeSpacingTest, ASwingsStrobeEndsAtTheTopAfterTheCollision) {
  constexpr double g = 9.81;
  // newtons-cradle: ball 1 falls from 30° on a 0.5 m string to the row (a quarter period), ball
  // 5 rises as high (another quarter period, the same amplitude: e = 1, equal masses).
  const double quarter_s = std::sqrt(0.5 / g) * std::comp_ellint_1(std::sin(std::numbers::pi / 12));
  // ballistic-pendulum: the 10 g bullet at 200 m/s meets the 1 kg block after (0.5 - 0.125) m
  // and both move on at 2 / 1.01 m/s (momentum), rising h = v² / 2g on the 1 m string.
  const double hit_s = (0.5 - 0.125) / 200.0;
  const double v_mps = 2.0 / 1.01, h_m = v_mps * v_mps / (2.0 * g);
  const double rise_s =
      hit_s + std::sqrt(1.0 / g) * std::comp_ellint_1(std::sin(0.5 * std::acos(1.0 - h_m)));
  for (const auto& [name, top_s] :
       {std::pair<std::string, double>{"newtons-cradle", 2.0 * quarter_s},
        std::pair<std::string, double>{"ballistic-pendulum", rise_s}}) {
    SCOPED_TRACE(name);
    const scene::SceneDesc scene = scene::loadPreset(name);
    const app::Animation animation = app::animate(scene, {640, 360});
    ASSERT_LT(top_s, scene.duration_s);
    // To the bisection's round-off of the time, far below a flash's 1 / 50 s.
    EXPECT_NEAR(animation.frames.strobeSpan_s(), top_s, 1e-6);
    // A rate the user gives photographs the whole run.
    EXPECT_EQ(animation.frames.strobeSpan_s(false), scene.duration_s);
    const frame::FrameModel frame = animation.frames.strobeFrame(0.0);
    EXPECT_EQ(frame.time_readout.rfind("t = 0–", 0), 0u) << frame.time_readout;
    // Each swing is pictured, not only where it starts and ends: ball 1's swing down and ball
    // 5's up, the block's rise; every image at a flash (imagesByBody) and none overlapping
    // (FirstImagesKeptAndNoImagesOverlapAtTheChosenRate).
    ASSERT_EQ(frame.panels.size(), 1u);
    const physics::Timeline& timeline = animation.frames.panelTimeline(0);
    const double end_s = animation.frames.strobeSpan_s();
    const std::vector<std::vector<Image>> images = imagesByBody(
        scene, timeline, frame.panels.front(), animation.frames.strobeRate_hz(), end_s);
    for (const std::string& body : motionsUnshown(scene, timeline, images, end_s))
      ADD_FAILURE() << body << " shows nothing of how it moved";
  }
}

// Images of one body stand at equal time steps, even where another body's last image lies on
// one: heavy-light's 10 kg cart at 1 m/s hits the 0.1 kg cart at rest; by momentum and energy the
// light cart leaves at 2·10/10.1 m/s ≈ 1.98 m/s and so is 1.98 m further on at each flash, and
// its image at 3 s, under the heavy cart's last one, is drawn over it rather than left out (its
// images stood 4 m, then 2 m apart: it seemed to slow down).
TEST(StrobeSpacingTest, AnImageUnderAnotherBodysLastIsDrawnOverIt) {
  const scene::SceneDesc scene = scene::loadPreset("heavy-light");
  const app::Animation animation = app::animate(scene, {640, 360});
  const compose::FrameSource& source = animation.frames;
  const double rate_hz = source.strobeRate_hz();
  const double end_s = source.strobeSpan_s();
  const frame::FrameModel chosen = source.strobeFrame(0.0);
  const physics::Timeline& timeline = source.panelTimeline(0);
  const std::vector<std::vector<Image>> images =
      imagesByBody(scene, timeline, chosen.panels[0], rate_hz, end_s);
  ASSERT_FALSE(timeline.collisions().empty());
  const double hit_s = timeline.collisions().front().time_s;
  const double m1 = scene.bodies[0].mass_kg, m2 = scene.bodies[1].mass_kg;
  const double v_light = 2.0 * m1 * scene.bodies[0].velocity_mps.x() / (m1 + m2);
  std::vector<double> xs;  // the light cart's flash images after the hit, in time order
  bool any_over = false;
  for (const Image& image : images[1]) {
    if (image.flash < 0 || image.t_s <= hit_s) continue;
    xs.push_back(image.center.x());
    any_over = any_over || image.over;
  }
  std::sort(xs.begin(), xs.end());
  // Every flash after the hit but the last (the solid image) is there.
  const int flashes = static_cast<int>(std::floor(end_s * rate_hz + 1e-9)) + 1;
  const int after_hit = flashes - 1 - static_cast<int>(std::floor(hit_s * rate_hz)) - 1;
  EXPECT_EQ(static_cast<int>(xs.size()), after_hit);
  for (std::size_t k = 1; k < xs.size(); ++k) {
    EXPECT_NEAR(xs[k] - xs[k - 1], v_light / rate_hz, 1e-6) << "image " << k;
  }
  EXPECT_TRUE(any_over) << "no image drawn over the heavy cart";
}
}  // namespace
}  // namespace collide
