// The renderer end to end on OSMesa: goldens, pixel-exact bar, resolution independence.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "frame/layout.hpp"
#include "frame_models.hpp"
#include "golden.hpp"
#include "png_io.hpp"
#include "render/gl/compiler_pages.hpp"
#include "render/renderer.hpp"

namespace collide::render {
namespace {

using testing::kBlue;
using testing::kGray;
using testing::kOrange;

double colorDistance(const std::uint8_t* p, const frame::Rgba& c) {
  const double dr = p[0] - 255.0 * c.r, dg = p[1] - 255.0 * c.g, db = p[2] - 255.0 * c.b;
  return std::sqrt(dr * dr + dg * dg + db * db);
}

// Index of the palette colour nearest to pixel p.
std::size_t nearest(const std::uint8_t* p, const std::vector<frame::Rgba>& palette) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < palette.size(); ++i) {
    if (colorDistance(p, palette[i]) < colorDistance(p, palette[best])) best = i;
  }
  return best;
}

bool isBackground(const std::uint8_t* p) {
  return p[0] == 255 && p[1] == 255 && p[2] == 255;
}

test::GoldenOptions goldenOptions(const Renderer& renderer) {
  test::GoldenOptions options;
  options.renderer = renderer.glRendererName();
  return options;
}

TEST(RendererGLTest, ReportsSizeAndLlvmpipe) {
  Renderer renderer(320, 180);
  EXPECT_EQ(renderer.width_px(), 320);
  EXPECT_EQ(renderer.height_px(), 180);
  EXPECT_NE(renderer.glRendererName().find("llvmpipe"), std::string::npos)
      << renderer.glRendererName();
}

TEST(RendererGLTest, FrameLargerThanGlAllowsIsARenderError) {
  try {
    Renderer renderer(40000, 90);
    FAIL() << "no error for a 40000 px wide frame";
  } catch (const RenderError& error) {
    EXPECT_NE(std::string(error.what()).find("40000x90 "), std::string::npos) << error.what();
  }
}

std::vector<std::uint8_t> pixelsOf(const core::ImageView& image) {
  std::vector<std::uint8_t> pixels;
  for (int y = 0; y < image.height; ++y) {
    pixels.insert(pixels.end(), image.row(y), image.row(y) + 4 * image.width);
  }
  return pixels;
}

TEST(RendererGLTest, FramesDrawnAfterLlvmsPagesWentAreTheSame) {
  // The second frame compiles every shader and gives LLVM's pages back; what is drawn after that,
  // and by a new context that compiles its shaders again, is the same as before.
  std::vector<std::uint8_t> first;
  {
    Renderer renderer(320, 180);
    first = pixelsOf(renderer.render(testing::labelledBlocks()));
    renderer.render(testing::twoDimensional());
    EXPECT_EQ(pixelsOf(renderer.render(testing::labelledBlocks())), first);
  }
  releaseCompilerPages();
  Renderer again(320, 180);
  EXPECT_EQ(pixelsOf(again.render(testing::labelledBlocks())), first);
}

// Resident file-backed pages of this process (/proc/self/statm's third field).
long residentFilePages() {
  std::FILE* statm = std::fopen("/proc/self/statm", "r");
  long size = 0, resident = 0, shared = -1;
  if (statm != nullptr) {
    if (std::fscanf(statm, "%ld %ld %ld", &size, &resident, &shared) != 3) shared = -1;
    std::fclose(statm);
  }
  return shared;
}

TEST(RendererGLTest, LlvmsPagesGoBackAfterCompiling) {
  // llvmpipe compiled the frame's shaders with LLVM, whose code pages are then resident; the
  // release finds libLLVM's read-only segments and drops them from this process.
  {
    Renderer renderer(320, 180);
    if (renderer.glRendererName().find("llvmpipe") == std::string::npos) {
      GTEST_SKIP() << "not llvmpipe: " << renderer.glRendererName();
    }
    renderer.render(testing::labelledBlocks());
  }
  const long before = residentFilePages();
  ASSERT_GT(before, 0);
  EXPECT_GT(releaseCompilerPages(), 0u);
  EXPECT_LT(residentFilePages(), before);
}

TEST(RendererGLTest, TwoBlocksMatchesGolden) {
  Renderer renderer(320, 180);
  const core::ImageView image = renderer.render(testing::twoBlocks());
  EXPECT_LT(image.row_stride, 0);  // bottom-up read-back, not copied
  EXPECT_TRUE(test::compareWithGolden(image, "render/two_blocks.png", goldenOptions(renderer)));
}

TEST(RendererGLTest, DiskTranslucentAndRestingMatchesGolden) {
  Renderer renderer(320, 180);
  const core::ImageView image = renderer.render(testing::diskAndTranslucent());
  EXPECT_TRUE(
      test::compareWithGolden(image, "render/disk_translucent.png", goldenOptions(renderer)));
}

// Text: title, time, labels with subscripts and primes, bar labels, info line, caption, ruler.
TEST(RendererGLTest, LabelledBlocksMatchesGolden) {
  Renderer renderer(480, 270);
  const core::ImageView image = renderer.render(testing::labelledBlocks());
  EXPECT_TRUE(
      test::compareWithGolden(image, "render/labelled_blocks.png", goldenOptions(renderer)));
}

// The golden comparison sees one changed character anywhere in the text: a digit of a mass, an
// energy, the time, or the sign of a velocity (each passed the old 0.1 %-of-pixels cap).
TEST(RendererGLTest, LabelledBlocksGoldenSeesOneChangedCharacter) {
  const core::Image golden = test::readPng(test::goldenSourceDir() + "/render/labelled_blocks.png");
  Renderer renderer(480, 270);
  const test::GoldenOptions options = goldenOptions(renderer);
  ASSERT_TRUE(
      test::judgeImages(renderer.render(testing::labelledBlocks()), golden.view(), options));
  const std::vector<std::pair<std::string, void (*)(frame::FrameModel&)>> changes = {
      {"m₁ 1.00 → 7.00",
       [](frame::FrameModel& f) { f.panels[0].bodies[0].label = "m₁ = 7.00 kg"; }},
      {"KE₁ 0.45 → 0.46",
       [](frame::FrameModel& f) { f.panels[0].energy_bar.segments[0].label = "KE₁ 0.46 J"; }},
      {"t 1.250 → 1.260", [](frame::FrameModel& f) { f.time_readout = "t = 1.260 s"; }},
      {"v₁′ + → −",
       [](frame::FrameModel& f) { f.panels[0].bodies[0].velocity_label = "v₁′ = −1.50 m/s"; }},
      {"v₂′ − → +",
       [](frame::FrameModel& f) { f.panels[0].bodies[1].velocity_label = "v₂′ = +0.50 m/s"; }},
      {"caption 15.0% → 16.0%",
       [](frame::FrameModel& f) {
         f.panels[0].caption = "t = 1.250 s: v₁′ = +1.50 m/s, v₂′ = −0.50 m/s; lost 0.15 J (16.0%)";
       }},
  };
  for (const auto& [what, change] : changes) {
    frame::FrameModel frame = testing::labelledBlocks();
    change(frame);
    EXPECT_FALSE(test::judgeImages(renderer.render(frame), golden.view(), options)) << what;
  }
}

TEST(RendererGLTest, TwoDimensionalSceneMatchesGolden) {
  Renderer renderer(480, 270);
  const core::ImageView image = renderer.render(testing::twoDimensional());
  EXPECT_TRUE(test::compareWithGolden(image, "render/two_d.png", goldenOptions(renderer)));
}

TEST(RendererGLTest, ChartMatchesGolden) {
  Renderer renderer(480, 270);
  const core::ImageView image = renderer.render(testing::chartOnly());
  EXPECT_TRUE(test::compareWithGolden(image, "render/chart.png", goldenOptions(renderer)));
}

TEST(RendererGLTest, TextIsCrispAndIdenticalEveryRun) {
  Renderer renderer(480, 270);
  const core::Image first = core::Image::copyOf(renderer.render(testing::labelledBlocks()));
  Renderer other(480, 270);
  const core::Image second = core::Image::copyOf(other.render(testing::labelledBlocks()));
  EXPECT_EQ(std::memcmp(first.data(), second.data(), 480 * 270 * 4), 0);
}

TEST(RendererGLTest, BarLabelsDoNotChangeTheSegments) {
  // The labelled frame's bar is the plain frame's bar, pixel for pixel.
  Renderer renderer(640, 360);
  const core::Image plain = core::Image::copyOf(renderer.render(testing::twoBlocks()));
  frame::FrameModel labelled = testing::twoBlocks();
  labelled.panels[0].energy_bar.segments[0].label = "KE₁ 0.45 J";
  labelled.panels[0].energy_bar.segments[2].label = "lost 0.15 J";
  const core::Image with = core::Image::copyOf(renderer.render(labelled));
  const frame::PixelRect outer = frame::computeFrameLayout(640, 360).panel().bar_outer;
  for (int y = static_cast<int>(outer.y0); y < static_cast<int>(outer.y1); ++y) {
    for (int x = static_cast<int>(outer.x0); x < static_cast<int>(outer.x1); ++x) {
      ASSERT_EQ(std::memcmp(plain.pixel(x, y), with.pixel(x, y), 4), 0) << x << "," << y;
    }
  }
}

TEST(RendererGLTest, MissingFontIsAFontError) {
  RendererOptions options;
  options.font_path = "/no/such.ttf";
  EXPECT_THROW(Renderer(64, 64, options), FontError);
}

TEST(RendererGLTest, EnergyBarSegmentsMatchEnergiesWithinATenthOfAPixel) {
  for (const auto& [w, h] : {std::pair{320, 180}, {640, 360}, {1280, 720}}) {
    Renderer renderer(w, h);
    const frame::FrameModel frame = testing::twoBlocks();
    const core::ImageView image = renderer.render(frame);
    const frame::FrameLayout layout = frame::computeFrameLayout(w, h);
    const frame::PixelRect inner = layout.panel().bar_inner;
    const int row = static_cast<int>(0.5 * (inner.y0 + inner.y1));

    // Measure each colour's width along the row: a pixel of one palette colour counts whole; a
    // pixel where two neighbours meet is split between them by where its colour lies on the line
    // from one to the other (the edge's coverage).
    const std::vector<frame::Rgba> palette = {kBlue, kOrange, kGray, frame.style.background};
    const auto pure = [&](int x) -> int {
      const std::size_t k = nearest(image.pixel(x, row), palette);
      return colorDistance(image.pixel(x, row), palette[k]) < 3.0 ? static_cast<int>(k) : -1;
    };
    std::vector<double> widths(palette.size(), 0.0);
    const int x0 = static_cast<int>(inner.x0), x1 = static_cast<int>(inner.x1);
    for (int x = x0; x < x1; ++x) {
      const int k = pure(x);
      if (k >= 0) {
        widths[k] += 1.0;
        continue;
      }
      const int before = x > x0 ? pure(x - 1) : -1, after = x + 1 < x1 ? pure(x + 1) : -1;
      ASSERT_TRUE(before >= 0 && after >= 0) << "a mixed pixel between mixed pixels at " << x;
      const frame::Rgba& a = palette[before];
      const frame::Rgba& b = palette[after];
      const std::uint8_t* p = image.pixel(x, row);
      double along = 0.0, span = 0.0;
      for (int c = 0; c < 3; ++c) {
        const double from = 255.0 * (&a.r)[c], to = 255.0 * (&b.r)[c];
        along += (p[c] - from) * (to - from);
        span += (to - from) * (to - from);
      }
      const double f = std::clamp(along / span, 0.0, 1.0);
      widths[before] += 1.0 - f;
      widths[after] += f;
    }
    const frame::EnergyBar& bar = frame.panels[0].energy_bar;
    for (std::size_t i = 0; i < bar.segments.size(); ++i) {
      const double expected_px = inner.width() * bar.segments[i].energy_J / bar.full_scale_J;
      EXPECT_NEAR(widths[i], expected_px, 0.1) << "segment " << i << " at " << w << "x" << h;
    }
    // The first segment starts right at the inner edge.
    EXPECT_LT(colorDistance(image.pixel(static_cast<int>(inner.x0), row), kBlue), 10.0);
  }
}

// Pixel extent [first, last] of a row's at-least-half-covered pixels within [x0, x1): those at
// least half as far from the white background as the row's strongest colour (the outline).
std::pair<int, int> rowExtent(const core::ImageView& image, int row, int x0, int x1) {
  const frame::Rgba white{1.0f, 1.0f, 1.0f, 1.0f};
  double strongest = 0.0;
  for (int x = x0; x < x1; ++x)
    strongest = std::max(strongest, colorDistance(image.pixel(x, row), white));
  int first = -1, last = -1;
  for (int x = x0; x < x1; ++x) {
    if (colorDistance(image.pixel(x, row), white) < 0.5 * strongest) continue;
    if (first < 0) first = x;
    last = x;
  }
  return {first, last};
}

TEST(RendererGLTest, PictureScalesWithFrameHeight) {
  const frame::FrameModel frame = testing::twoBlocks();
  const frame::BodyModel& body = frame.panels[0].bodies[1];
  std::vector<double> widths_px;
  for (const auto& [w, h] : {std::pair{640, 360}, {1280, 720}}) {
    Renderer renderer(w, h);
    const core::ImageView image = renderer.render(frame);
    const frame::FrameLayout layout = frame::computeFrameLayout(w, h);
    const frame::WorldToPixel to_px = frame::panelMapping(frame.panels[0], layout.panel(), layout);
    const core::Vec2 center = to_px.toPixel(body.center_m);
    const double half_px = body.half_extent_m.x() * to_px.px_per_m;
    const auto [first, last] =
        rowExtent(image, static_cast<int>(center.y()), static_cast<int>(center.x() - 2 * half_px),
                  static_cast<int>(center.x() + 2 * half_px));
    ASSERT_GE(first, 0);
    const double width = last - first + 1;
    // Both edges are anti-aliased: up to a pixel of rounding at each.
    EXPECT_NEAR(width, 2.0 * half_px, 1.5) << w << "x" << h;
    widths_px.push_back(width);
  }
  EXPECT_NEAR(widths_px[1] / widths_px[0], 2.0, 2.0 / widths_px[0]);
}

TEST(RendererGLTest, RenderingTwiceGivesIdenticalBytes) {
  Renderer renderer(320, 180);
  const frame::FrameModel frame = testing::diskAndTranslucent();
  const core::Image first = core::Image::copyOf(renderer.render(frame));
  renderer.render(testing::twoBlocks());  // something else in between
  const core::Image second = core::Image::copyOf(renderer.render(frame));
  EXPECT_EQ(std::memcmp(first.data(), second.data(), 320 * 180 * 4), 0);
}

TEST(RendererGLTest, AFrameStaysWholeWhileTheNextIsDrawn) {
  // The video path converts frame k on another thread while frame k + 1 is drawn and read back.
  Renderer renderer(320, 180);
  const core::Image expected = core::Image::copyOf(renderer.render(testing::twoBlocks()));
  const core::ImageView kept = renderer.render(testing::twoBlocks());
  frame::FrameModel other = testing::diskAndTranslucent();
  other.style.background = {0.1f, 0.2f, 0.3f, 1.0f};  // every pixel differs from the kept frame's
  const core::ImageView next = renderer.render(other);
  EXPECT_NE(next.pixel(1, 1)[0], kept.pixel(1, 1)[0]);
  for (int y = 0; y < 180; ++y) {
    ASSERT_EQ(std::memcmp(kept.row(y), expected.view().row(y), 320 * 4), 0) << "row " << y;
  }
}

TEST(RendererGLTest, BodyAtRestHasNoArrow) {
  frame::FrameModel frame = testing::twoBlocks();
  Renderer renderer(640, 360);
  const frame::FrameLayout layout = frame::computeFrameLayout(640, 360);
  const frame::WorldToPixel to_px = frame::panelMapping(frame.panels[0], layout.panel(), layout);
  const frame::BodyModel& body = frame.panels[0].bodies[0];
  const core::Vec2 center = to_px.toPixel(body.center_m);
  const double half_px = body.half_extent_m.x() * to_px.px_per_m;
  // The region above the body, up to the frame top, across the body's width.
  const auto darkPixelsAbove = [&](const core::ImageView& image) {
    int dark = 0;
    for (int y = 0; y < static_cast<int>(center.y() - half_px) - 1; ++y) {
      for (int x = static_cast<int>(center.x() - half_px); x <= center.x() + half_px; ++x) {
        if (!isBackground(image.pixel(x, y))) ++dark;
      }
    }
    return dark;
  };
  EXPECT_GT(darkPixelsAbove(renderer.render(frame)), 0);  // moving: an arrow is there
  frame.panels[0].bodies[0].velocity_mps = {0.0, 0.0};
  EXPECT_EQ(darkPixelsAbove(renderer.render(frame)), 0);
}

TEST(RendererGLTest, TranslucentBackgroundComesBackAsStraightAlpha) {
  frame::FrameModel frame = testing::twoBlocks();
  frame.style.background = {0.2f, 0.4f, 0.6f, 0.5f};
  Renderer renderer(320, 180);
  const core::ImageView image = renderer.render(frame);
  // Colour went through 8-bit premultiplied storage: ±0.5 level at alpha 0.5 is ±1 straight, plus
  // alpha's own rounding.
  const std::uint8_t* corner = image.pixel(1, 1);
  EXPECT_NEAR(corner[0], 51, 2);
  EXPECT_NEAR(corner[1], 102, 2);
  EXPECT_NEAR(corner[2], 153, 2);
  EXPECT_NEAR(corner[3], 128, 1);
}

TEST(RendererGLTest, TwoRenderersCanLiveSideBySide) {
  Renderer small(160, 90);
  Renderer large(320, 180);
  const core::Image a = core::Image::copyOf(small.render(testing::twoBlocks()));
  const core::Image b = core::Image::copyOf(large.render(testing::twoBlocks()));
  const core::Image a_again = core::Image::copyOf(small.render(testing::twoBlocks()));
  EXPECT_EQ(a.width(), 160);
  EXPECT_EQ(b.width(), 320);
  EXPECT_EQ(std::memcmp(a.data(), a_again.data(), 160 * 90 * 4), 0);
}

}  // namespace
}  // namespace collide::render
