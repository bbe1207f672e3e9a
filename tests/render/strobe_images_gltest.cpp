// SPDX-License-Identifier: MIT
// A strobe's faint images as the renderer draws them, on hand-built frames (issue 37 item 4): an
// image drawn over a solid body (a body's first image under its last) shows its whole edge there,
// where its faint fill barely tints the body; an image's bumpers are drawn with it.
#include <gtest/gtest.h>

#include <cmath>

#include "frame/layout.hpp"
#include "frame_models.hpp"
#include "render/renderer.hpp"

namespace collide::render {
namespace {

constexpr int kStrobeWidth_px = 640, kStrobeHeight_px = 360;
constexpr float kFaintAlpha = 0.18f;  // a strobe's earliest image

bool nearlyBackground(const std::uint8_t* p) {
  return p[0] >= 250 && p[1] >= 250 && p[2] >= 250;
}

// twoBlocks at rest (no arrows) with one faint image of the left block, `shift_m` along x.
frame::FrameModel withImage(double shift_m, bool over_bodies) {
  frame::FrameModel frame = testing::twoBlocks();
  frame::PanelModel& panel = frame.panels[0];
  for (frame::BodyModel& body : panel.bodies) body.velocity_mps = {0.0, 0.0};
  frame::BodyModel image = panel.bodies[0];
  image.center_m.x() += shift_m;
  image.fill.a = kFaintAlpha;
  image.over_bodies = over_bodies;
  panel.ghosts = {image};
  return frame;
}

TEST(StrobeImagesGLTest, AnImageOverASolidBodyShowsItsWholeEdge) {
  Renderer renderer(kStrobeWidth_px, kStrobeHeight_px);
  const frame::FrameLayout layout = frame::computeFrameLayout(kStrobeWidth_px, kStrobeHeight_px);
  // The image 0.1 m left of the block: its right edge lies on the block, 0.1 m inside it.
  const frame::FrameModel over = withImage(-0.1, true);
  const frame::WorldToPixel to_px = frame::panelMapping(over.panels[0], layout.panel(), layout);
  const frame::BodyModel& image = over.panels[0].ghosts[0];
  const core::Vec2 center = to_px.toPixel(image.center_m);
  const double right_edge = center.x() + to_px.px_per_m * image.half_extent_m.x();
  ASSERT_GT(layout.outline_px, 1.0);
  // Just inside that edge, on the block: where the image's edge stands out of the body.
  const int x = static_cast<int>(std::lround(right_edge - 1.5 * layout.outline_px));
  const int y = static_cast<int>(std::lround(center.y()));
  const std::uint8_t* drawn = renderer.render(over).pixel(x, y);
  EXPECT_TRUE(nearlyBackground(drawn)) << "(" << int(drawn[0]) << ", " << int(drawn[1]) << ", "
                                       << int(drawn[2]) << ") at " << x << ", " << y;
  // Under the bodies (the earlier images) the block hides it there: the check has teeth.
  const std::uint8_t* under = renderer.render(withImage(-0.1, false)).pixel(x, y);
  EXPECT_FALSE(nearlyBackground(under));
}

TEST(StrobeImagesGLTest, AnImagesBumpersAreDrawnWithIt) {
  Renderer renderer(kStrobeWidth_px, kStrobeHeight_px);
  const frame::FrameLayout layout = frame::computeFrameLayout(kStrobeWidth_px, kStrobeHeight_px);
  // An image well left of both blocks, with a bumper on each face.
  frame::FrameModel frame = withImage(-1.3, false);
  frame::BodyModel& image = frame.panels[0].ghosts[0];
  constexpr double kBumper_m = 0.2;
  for (const double side : {-1.0, 1.0}) {
    frame::SpringModel bumper;
    bumper.from_m = image.center_m + core::Vec2{side * image.half_extent_m.x(), 0.0};
    bumper.to_m = bumper.from_m + core::Vec2{side * kBumper_m, 0.0};
    bumper.half_width_m = 0.05;
    bumper.turns = 2;
    image.bumpers.push_back(bumper);
  }
  const frame::WorldToPixel to_px = frame::panelMapping(frame.panels[0], layout.panel(), layout);
  // The pixels beside each face, as far out as a bumper reaches, across its zigzag.
  const auto drawnBeside = [&](const core::ImageView& picture) {
    int drawn = 0;
    for (const frame::SpringModel& bumper : image.bumpers) {
      const core::Vec2 a = to_px.toPixel(bumper.from_m), b = to_px.toPixel(bumper.to_m);
      const double half_px = to_px.px_per_m * bumper.half_width_m;
      for (int x = static_cast<int>(std::min(a.x(), b.x())) + 2;
           x < static_cast<int>(std::max(a.x(), b.x())) - 1; ++x) {
        for (int y = static_cast<int>(a.y() - half_px); y <= a.y() + half_px; ++y)
          drawn += nearlyBackground(picture.pixel(x, y)) ? 0 : 1;
      }
    }
    return drawn;
  };
  EXPECT_GT(drawnBeside(renderer.render(frame)), 0) << "no bumper beside the image";
  frame::FrameModel bare = frame;
  bare.panels[0].ghosts[0].bumpers.clear();
  EXPECT_EQ(drawnBeside(renderer.render(bare)), 0);
}

}  // namespace
}  // namespace collide::render
