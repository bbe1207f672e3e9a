// SPDX-License-Identifier: MIT
// The skid measured on accident-reconstruction's picture (issue 40 item 1), checked on the frame
// description and its layout: from the impact on, a horizontal dimension "skid.1" spans the
// locked pair's travel since the impact, ending at car 1's rear face, labelled with that length;
// none before the impact nor without friction; its label clear of every other drawn thing.
// Every expected number from the scene's own masses, coefficients and places by closed forms:
// car 1 skids the gap s first, v² = v₀² − 2μg s; the lock shares its momentum,
// v′ = m₁ v / (m₁ + m₂); the pair then skids d(τ) = v′τ − ½μgτ² to rest at d = v′²/(2μg).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "app/animation.hpp"
#include "render/frame_layout.hpp"
#include "scene/scene_desc.hpp"
#include "text/language.hpp"

namespace collide {
namespace {

// The accident worked out from the scene alone.
struct Accident {
  double impact_s = 0.0, rest_s = 0.0;
  double v_after_mps = 0.0, decel_mps2 = 0.0;
  double rear_at_impact_m = 0.0;  // car 1's rear face at the impact

  double skid_m(double t_s) const {
    const double tau = std::min(t_s, rest_s) - impact_s;
    return v_after_mps * tau - 0.5 * decel_mps2 * tau * tau;
  }
  double final_m() const { return v_after_mps * v_after_mps / (2.0 * decel_mps2); }
};

Accident workedOut(const scene::SceneDesc& scene) {
  const scene::BodyDesc &car1 = scene.bodies.at(0), &car2 = scene.bodies.at(1);
  Accident a;
  a.decel_mps2 = car1.friction * scene.surface_gravity_mps2;
  const double v0 = car1.velocity_mps.x();
  const double gap =
      (car2.position_m.x() - 0.5 * car2.size_m) - (car1.position_m.x() + 0.5 * car1.size_m);
  const double v_impact = std::sqrt(v0 * v0 - 2.0 * a.decel_mps2 * gap);
  a.impact_s = (v0 - v_impact) / a.decel_mps2;
  a.v_after_mps = car1.mass_kg * v_impact / (car1.mass_kg + car2.mass_kg);
  a.rest_s = a.impact_s + a.v_after_mps / a.decel_mps2;
  a.rear_at_impact_m = car1.position_m.x() - 0.5 * car1.size_m + gap;
  return a;
}

// The skid's length as the picture reads it: three figures of the longest skid, 7.60 m, so
// two decimals throughout.
std::string reading(double d_m) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f m", d_m);
  return text;
}

const frame::DimensionModel* skidOf(const frame::FrameModel& frame) {
  for (const frame::DimensionModel& dim : frame.panels.at(0).dimensions) {
    if (dim.id == "skid.1") return &dim;
  }
  return nullptr;
}

bool overlap(const frame::PixelRect& a, const frame::PixelRect& b) {
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

// The label's box overlaps nothing else the frame draws but its own line.
void expectLabelClear(const frame::FrameModel& frame, const frame::DimensionModel& skid, int w,
                      int h) {
  ASSERT_TRUE(skid.label_at.has_value()) << "the skid's label found no place";
  const frame::PlacedText& at = *skid.label_at;
  const frame::PixelRect label{at.top_left_px.x(), at.top_left_px.y(),
                               at.top_left_px.x() + at.size_px.x(),
                               at.top_left_px.y() + at.size_px.y()};
  EXPECT_GE(label.x0, 0.0);
  EXPECT_LE(label.x1, w);
  for (const frame::DrawnItem& item : render::drawnItems(frame, w, h)) {
    if (item.id == "skid.1") {
      EXPECT_EQ(item.kind, "dimension");
      ASSERT_EQ(item.lines.size(), 1u);
      EXPECT_EQ(item.lines.front(), skid.label);
      continue;
    }
    EXPECT_FALSE(overlap(label, item.box)) << "\"" << skid.label << "\" overlaps " << item.id;
  }
}

TEST(SkidDimensionTest, SpansThePairsTravelSinceTheImpactLabelledWithIt) {
  const text::ScopedLanguage english("en");
  const scene::SceneDesc scene = scene::loadPreset("accident-reconstruction");
  const Accident a = workedOut(scene);
  for (const auto& [w, h] : {std::pair{1280, 720}, std::pair{640, 360}}) {
    const app::Animation animation = app::animate(scene, {w, h});
    for (const double t_s :
         {a.impact_s + 0.05, a.impact_s + 0.6, a.rest_s - 0.1, scene.duration_s}) {
      SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h) + " at " + std::to_string(t_s));
      const frame::FrameModel frame = animation.frames.frameAtSimulated(t_s);
      const frame::DimensionModel* skid = skidOf(frame);
      ASSERT_NE(skid, nullptr);
      EXPECT_EQ(skid->axis, frame::DimensionAxis::kHorizontal);
      const double d = a.skid_m(t_s);
      EXPECT_NEAR(skid->from_m.x(), a.rear_at_impact_m, 1e-9);
      EXPECT_NEAR(skid->to_m.x(), a.rear_at_impact_m + d, 1e-9);
      // It ends at car 1's rear face as drawn.
      const frame::BodyModel& car1 = frame.panels.at(0).bodies.at(0);
      EXPECT_NEAR(skid->to_m.x(), car1.center_m.x() - car1.half_extent_m.x(), 1e-9);
      EXPECT_EQ(skid->label, "skid d = " + reading(d));
      expectLabelClear(frame, *skid, w, h);
    }
  }
}

TEST(SkidDimensionTest, TheStrobeMeasuresTheWholeSkid) {
  const text::ScopedLanguage english("en");
  const scene::SceneDesc scene = scene::loadPreset("accident-reconstruction");
  const Accident a = workedOut(scene);
  const app::Animation animation = app::animate(scene, {1280, 720});
  const frame::FrameModel strobe = animation.frames.strobeFrame(0.0);
  const frame::DimensionModel* skid = skidOf(strobe);
  ASSERT_NE(skid, nullptr);
  EXPECT_NEAR(skid->to_m.x() - skid->from_m.x(), a.final_m(), 1e-9);
  EXPECT_EQ(skid->label, "skid d = " + reading(a.final_m()));
  expectLabelClear(strobe, *skid, 1280, 720);
}

TEST(SkidDimensionTest, NoneBeforeTheImpactNorWithoutFriction) {
  const text::ScopedLanguage english("en");
  scene::SceneDesc scene = scene::loadPreset("accident-reconstruction");
  const Accident a = workedOut(scene);
  {
    const app::Animation animation = app::animate(scene, {640, 360});
    for (const double t_s : {0.0, a.impact_s - 0.02}) {
      EXPECT_TRUE(animation.frames.frameAtSimulated(t_s).panels.at(0).dimensions.empty())
          << "at " << t_s << " s";
    }
  }
  // The same crash on ice: the pair locks and slides on, skidding nowhere.
  for (scene::BodyDesc& car : scene.bodies) {
    car.friction = 0.0;
    car.static_friction.reset();
  }
  const app::Animation on_ice = app::animate(scene, {640, 360});
  EXPECT_TRUE(on_ice.frames.frameAtSimulated(scene.duration_s).panels.at(0).dimensions.empty());
}

}  // namespace
}  // namespace collide
