// SPDX-License-Identifier: MIT
// Texts fading in or out (frame::PlacedText::opacity) through the GL painter: a label, its leader
// and a legend line are drawn over the background at their colour's alpha times their opacity, and
// at opacity 0 not at all.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "frame_models.hpp"
#include "render/frame_layout.hpp"
#include "render/renderer.hpp"

namespace collide::render {
namespace {

constexpr int kWidthPx = 1280;  // text of 720p: its stems are whole pixels wide, fully covered
constexpr int kHeightPx = 720;
constexpr float kLabelOpacity = 0.5f;
constexpr float kLegendOpacity = 0.25f;

struct Picture {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;
  const std::uint8_t* at(int x, int y) const { return rgba.data() + 4 * (y * width + x); }
};

Picture rendered(Renderer& renderer, const frame::FrameModel& frame) {
  const core::ImageView image = renderer.render(frame);
  Picture picture{image.width, image.height, {}};
  for (int y = 0; y < image.height; ++y) {
    picture.rgba.insert(picture.rgba.end(), image.row(y), image.row(y) + 4 * image.width);
  }
  return picture;
}

// The pixels whose centres lie in `box`, as whole-pixel bounds [x0, x1) × [y0, y1).
struct Pixels {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool holds(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
};

Pixels pixelsIn(const frame::PixelRect& box) {
  return {static_cast<int>(std::ceil(box.x0 - 0.5)), static_cast<int>(std::ceil(box.y0 - 0.5)),
          static_cast<int>(std::ceil(box.x1 - 0.5)), static_cast<int>(std::ceil(box.y1 - 0.5))};
}

frame::PixelRect grown(const frame::PixelRect& box, double by_px) {
  return {box.x0 - by_px, box.y0 - by_px, box.x1 + by_px, box.y1 + by_px};
}

// The red channel of the darkest pixel among `where` (the colours here are greys on white).
int darkest(const Picture& picture, const Pixels& where) {
  int lowest = 255;
  for (int y = where.y0; y < where.y1; ++y) {
    for (int x = where.x0; x < where.x1; ++x) lowest = std::min<int>(lowest, picture.at(x, y)[0]);
  }
  return lowest;
}

frame::PixelRect boxOf(const std::vector<frame::DrawnItem>& items, const std::string& id) {
  for (const frame::DrawnItem& item : items) {
    if (item.id == id) return item.box;
  }
  ADD_FAILURE() << "no item " << id;
  return {};
}

// `a` of `over` over `under` (one channel, 0 to 255): "over" compositing at alpha a.
double blend(double over, double under, double a) {
  return a * over + (1.0 - a) * under;
}

// Where the texts and the leader of testing::fadingLabels are drawn at this size.
struct Places {
  Pixels label, leader, legend;
};

Places placesOf(const frame::FrameModel& solid) {
  const std::vector<frame::DrawnItem> items = drawnItems(solid, kWidthPx, kHeightPx);
  Places places;
  // One pixel more on every side: anti-aliased edges.
  places.label = pixelsIn(grown(boxOf(items, "mass.1"), 1.0));
  places.legend = pixelsIn(grown(boxOf(items, "legend.velocity.1"), 1.0));
  // The leader's run between its ends, clear of the label it starts at.
  const frame::PlacedText& at = *solid.panels[0].bodies[0].label_at;
  const frame::PixelRect line = grown(boxOf(items, "leader.mass.1"), 1.0);
  places.leader =
      pixelsIn({at.leader_to_px->x() + 2.0, line.y0, at.top_left_px.x() - 2.0, line.y1});
  return places;
}

TEST(TextOpacityGLTest, AFadingLabelItsLeaderAndALegendLineBlendWithTheBackground) {
  Renderer renderer(kWidthPx, kHeightPx);
  const frame::FrameModel solid_frame = testing::fadingLabels(kWidthPx, kHeightPx, 1.0f, 1.0f);
  const Picture solid = rendered(renderer, solid_frame);
  const Picture faded =
      rendered(renderer, testing::fadingLabels(kWidthPx, kHeightPx, kLabelOpacity, kLegendOpacity));
  const Places places = placesOf(solid_frame);
  const frame::FrameStyle& style = solid_frame.style;
  const double background = 255.0 * style.background.r;
  const double text = 255.0 * style.text.r;

  // Solid, a text's darkest pixel is its colour: some pixel of its stems is wholly covered.
  EXPECT_NEAR(darkest(solid, places.label), text, 1.0);
  EXPECT_NEAR(darkest(solid, places.legend), text, 1.0);
  // Faded, that pixel is the text's colour at alpha = opacity over the background.
  EXPECT_NEAR(darkest(faded, places.label), blend(text, background, kLabelOpacity), 1.0);
  EXPECT_NEAR(darkest(faded, places.legend), blend(text, background, kLegendOpacity), 1.0);
  // The leader is thinner than a pixel: its darkest pixel, solid, is the muted colour at its
  // coverage c, background + c (muted - background); faded, at coverage c times the opacity.
  const double solid_leader = darkest(solid, places.leader);
  EXPECT_LT(solid_leader, background - 0.25 * (background - 255.0 * style.muted_text.r));
  EXPECT_NEAR(darkest(faded, places.leader), blend(solid_leader, background, kLabelOpacity), 1.0);

  // Nothing else changes.
  int changed_elsewhere = 0;
  for (int y = 0; y < kHeightPx; ++y) {
    for (int x = 0; x < kWidthPx; ++x) {
      if (places.label.holds(x, y) || places.legend.holds(x, y)) continue;
      // The leader's ends, round its run, are anti-aliased too.
      if (pixelsIn(grown({double(places.leader.x0), double(places.leader.y0),
                          double(places.leader.x1), double(places.leader.y1)},
                         3.0))
              .holds(x, y)) {
        continue;
      }
      if (!std::equal(solid.at(x, y), solid.at(x, y) + 4, faded.at(x, y))) ++changed_elsewhere;
    }
  }
  EXPECT_EQ(changed_elsewhere, 0);
}

TEST(TextOpacityGLTest, AtOpacityZeroTheTextsAndTheLeaderDrawNothing) {
  Renderer renderer(kWidthPx, kHeightPx);
  const frame::FrameModel solid_frame = testing::fadingLabels(kWidthPx, kHeightPx, 1.0f, 1.0f);
  const Places places = placesOf(solid_frame);
  const Picture gone = rendered(renderer, testing::fadingLabels(kWidthPx, kHeightPx, 0.0f, 0.0f));
  // The same frame with neither the label nor the legend line.
  frame::FrameModel bare = solid_frame;
  bare.panels[0].bodies[0].label_at.reset();
  bare.panels[0].legend.entries.clear();
  const Picture without = rendered(renderer, bare);
  const frame::Rgba& bg = solid_frame.style.background;
  const std::uint8_t background[3] = {static_cast<std::uint8_t>(std::lround(255.0 * bg.r)),
                                      static_cast<std::uint8_t>(std::lround(255.0 * bg.g)),
                                      static_cast<std::uint8_t>(std::lround(255.0 * bg.b))};
  for (const Pixels& where : {places.label, places.leader, places.legend}) {
    int not_background = 0;
    for (int y = where.y0; y < where.y1; ++y) {
      for (int x = where.x0; x < where.x1; ++x) {
        if (!std::equal(background, background + 3, gone.at(x, y))) ++not_background;
      }
    }
    EXPECT_EQ(not_background, 0) << "in the pixels from (" << where.x0 << ", " << where.y0 << ")";
  }
  EXPECT_TRUE(gone.rgba == without.rgba);
}

}  // namespace
}  // namespace collide::render
