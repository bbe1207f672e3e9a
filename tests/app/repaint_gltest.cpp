// A video's frames drawn where they change only (render/draw/repaint_regions.hpp) against the same
// frames drawn whole: byte for byte the same pixels, in playback order and in jumps, read back
// whole or only where they changed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "render/renderer.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

constexpr int kWidth = 320, kHeight = 180;

render::RendererOptions drawnWhole() {
  render::RendererOptions options;
  options.repaint_changes_only = false;
  return options;
}

// Renders `times` with both renderers in the given order: no frame may differ.
void expectSamePixels(const std::string& preset, const std::vector<double>& times,
                      bool transparent = false) {
  const compose::FrameSource source =
      app::animate(scene::loadPreset(preset), {kWidth, kHeight}).frames;
  render::Renderer changes_only(kWidth, kHeight);
  render::Renderer whole(kWidth, kHeight, drawnWhole());
  int differing = 0;
  for (double t : times) {
    frame::FrameModel frame = source.frameAt(t);
    if (transparent) frame.style.background.a = 0.0f;
    const core::Image a = core::Image::copyOf(changes_only.render(frame));
    const core::Image b = core::Image::copyOf(whole.render(frame));
    if (std::memcmp(a.data(), b.data(), 4u * kWidth * kHeight) != 0) {
      if (++differing <= 3) ADD_FAILURE() << preset << " at t = " << t << " s differs";
    }
  }
  EXPECT_EQ(differing, 0) << preset << ": frames that differ of " << times.size();
}

std::vector<double> playback(double duration_s, double fps) {
  std::vector<double> times;
  for (int k = 0; k / fps <= duration_s; ++k) times.push_back(k / fps);
  return times;
}

TEST(RepaintGLTest, FramesDrawnWhereTheyChangeEqualFramesDrawnWhole) {
  // One-dimensional carts with flashes and a bar, a 2D break of many balls, a pendulum's swing,
  // a chain of touching balls, three comparison panels.
  for (const std::string preset : {"worked-example", "billiards-break", "ballistic-pendulum",
                                   "newtons-cradle", "compare-restitution"}) {
    const compose::FrameSource source =
        app::animate(scene::loadPreset(preset), {kWidth, kHeight}).frames;
    expectSamePixels(preset, playback(std::min(source.duration_s(), 4.0), 10.0));
  }
}

TEST(RepaintGLTest, JumpsBackAndForthEqualFramesDrawnWhole) {
  expectSamePixels("worked-example", {2.5, 0.0, 1.2, 1.2, 10.0, 0.05, 9.95, 1.25, 1.3});
}

// A transparent video's pixels are converted to straight alpha after reading: still the same.
TEST(RepaintGLTest, TransparentFramesEqualFramesDrawnWhole) {
  expectSamePixels("worked-example", playback(2.0, 10.0), true);
}

// A frame that shows new glyphs (a velocity's new digits) is drawn only where it changed too: the
// glyph atlas grows without moving a glyph. Only the first frame, and the third (the renderer
// draws on its framebuffer to compile every shader after the second), are drawn whole.
TEST(RepaintGLTest, FramesWithNewGlyphsAreDrawnOnlyWhereTheyChange) {
  // At 720p60 the worked example's first 1.5 s show new digits in 7 frames after the third.
  const int width = 1280, height = 720;
  const compose::FrameSource source =
      app::animate(scene::loadPreset("worked-example"), {width, height}).frames;
  render::Renderer renderer(width, height);
  int frame = 0, drawn_whole = 0;
  for (double t : playback(1.5, 60.0)) {
    renderer.render(source.frameAt(t));
    const bool may_be_whole = frame == 0 || frame == 2;
    ++frame;
    if (!may_be_whole && renderer.changedRects() == nullptr) {
      if (++drawn_whole <= 3) ADD_FAILURE() << "frame at t = " << t << " s drawn whole";
    }
  }
  EXPECT_EQ(drawn_whole, 0);
}

// What a video's converter relies on (render/renderer.hpp): outside the rectangles changedRects()
// gives, a frame's pixels are those of the frame before, byte for byte.
TEST(RepaintGLTest, PixelsOutsideTheChangedRectanglesEqualTheFrameBefore) {
  for (const std::string preset : {"worked-example", "billiards-break", "newtons-cradle"}) {
    const compose::FrameSource source =
        app::animate(scene::loadPreset(preset), {kWidth, kHeight}).frames;
    render::Renderer renderer(kWidth, kHeight);
    core::Image before;
    int frames_with_rects = 0, pixels_given = 0, pixels_changed = 0;
    for (double t : playback(std::min(source.duration_s(), 3.0), 30.0)) {
      const core::Image now = core::Image::copyOf(renderer.render(source.frameAt(t)));
      const std::vector<core::ImageRect>* rects = renderer.changedRects();
      if (rects != nullptr) {
        ASSERT_GT(before.width(), 0) << preset << ": rectangles given for the first frame";
        ++frames_with_rects;
        std::vector<int> given(kWidth * kHeight, 0);
        for (const core::ImageRect& r : *rects) {
          ASSERT_TRUE(0 <= r.x0 && r.x0 < r.x1 && r.x1 <= kWidth && 0 <= r.y0 && r.y0 < r.y1 &&
                      r.y1 <= kHeight)
              << preset << " at t = " << t << " s: a rectangle inside the frame";
          for (int y = r.y0; y < r.y1; ++y) {
            for (int x = r.x0; x < r.x1; ++x) ++given[y * kWidth + x];
          }
        }
        for (int y = 0; y < kHeight; ++y) {
          for (int x = 0; x < kWidth; ++x) {
            const bool same = std::memcmp(now.pixel(x, y), before.pixel(x, y), 4) == 0;
            ASSERT_LE(given[y * kWidth + x], 1) << preset << ": rectangles overlap";
            pixels_given += given[y * kWidth + x];
            pixels_changed += same ? 0 : 1;
            if (given[y * kWidth + x] == 0) {
              ASSERT_TRUE(same) << preset << " at t = " << t << " s: pixel " << x << "," << y;
            }
          }
        }
      }
      before = now;
    }
    // Frames after the first give their rectangles, which hold fewer pixels than the frames.
    EXPECT_GT(frames_with_rects, 0) << preset;
    EXPECT_LT(pixels_given, frames_with_rects * kWidth * kHeight) << preset;
    EXPECT_GT(pixels_changed, 0) << preset;
  }
}

}  // namespace
}  // namespace collide
