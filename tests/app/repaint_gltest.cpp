// A video's frames drawn where they change only (render/repaint_regions.hpp) against the same
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
    render::FrameModel frame = source.frameAt(t);
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

// What a video's converter relies on (render/renderer.hpp): outside the rows changedRows() gives,
// a frame's pixels are those of the frame before, byte for byte.
TEST(RepaintGLTest, RowsOutsideTheChangedRowsEqualTheFrameBefore) {
  const std::size_t row_bytes = 4u * kWidth;
  for (const std::string preset : {"worked-example", "billiards-break", "newtons-cradle"}) {
    const compose::FrameSource source =
        app::animate(scene::loadPreset(preset), {kWidth, kHeight}).frames;
    render::Renderer renderer(kWidth, kHeight);
    core::Image before;
    int frames_with_rows = 0, rows_given = 0, rows_changed = 0;
    for (double t : playback(std::min(source.duration_s(), 3.0), 30.0)) {
      const core::Image now = core::Image::copyOf(renderer.render(source.frameAt(t)));
      const std::vector<core::RowSpan>* rows = renderer.changedRows();
      if (rows != nullptr) {
        ASSERT_GT(before.width(), 0) << preset << ": rows given for the first frame";
        ++frames_with_rows;
        std::vector<bool> given(kHeight, false);
        int previous_end = -1;
        for (const core::RowSpan& span : *rows) {
          ASSERT_TRUE(0 <= span.first && span.first < span.end && span.end <= kHeight &&
                      span.first > previous_end)
              << preset << " at t = " << t << " s: spans in order, apart, inside the frame";
          previous_end = span.end;
          for (int y = span.first; y < span.end; ++y) given[y] = true;
        }
        for (int y = 0; y < kHeight; ++y) {
          const bool same = std::memcmp(now.data() + y * row_bytes, before.data() + y * row_bytes,
                                        row_bytes) == 0;
          rows_given += given[y] ? 1 : 0;
          rows_changed += same ? 0 : 1;
          if (!given[y]) {
            ASSERT_TRUE(same) << preset << " at t = " << t << " s: row " << y;
          }
        }
      }
      before = now;
    }
    // Frames after the first give their rows, and fewer than all of them.
    EXPECT_GT(frames_with_rows, 0) << preset;
    EXPECT_LT(rows_given, frames_with_rows * kHeight) << preset;
    EXPECT_GT(rows_changed, 0) << preset;
  }
}

}  // namespace
}  // namespace collide
