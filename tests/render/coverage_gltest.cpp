// Analytic anti-aliasing against geometry: a white disk and a rotated white block drawn on black
// with one sample per pixel; each pixel's red level must be the exact fraction of the pixel the
// shape covers, computed here from the shape itself (polygon clipping, integration), not from the
// renderer's formulas.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <numbers>
#include <vector>

#include "render/backend.hpp"
#include "render/draw/canvas.hpp"
#include "render/gl/canvas_painter.hpp"
#include "render/gl/framebuffers.hpp"
#include "render/renderer.hpp"
#include "render/text/font_set.hpp"
#include "render/text/glyph_atlas.hpp"
#include "render/text/text.hpp"

namespace collide::render {
namespace {

constexpr int kSize = 64;  // frame side, pixels
constexpr frame::Rgba kWhite{1.0f, 1.0f, 1.0f, 1.0f};
constexpr frame::Rgba kBlack{0.0f, 0.0f, 0.0f, 1.0f};

using Polygon = std::vector<core::Vec2>;

// Sutherland–Hodgman: the part of `polygon` on the side of the line through a with inward normal n.
Polygon clip(const Polygon& polygon, const core::Vec2& a, const core::Vec2& n) {
  Polygon out;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const core::Vec2 p = polygon[i], q = polygon[(i + 1) % polygon.size()];
    const double dp = (p - a).dot(n), dq = (q - a).dot(n);
    if (dp >= 0.0) out.push_back(p);
    if ((dp >= 0.0) != (dq >= 0.0)) out.push_back(p + (dp / (dp - dq)) * (q - p));
  }
  return out;
}

double area(const Polygon& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const core::Vec2 p = polygon[i], q = polygon[(i + 1) % polygon.size()];
    twice += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * std::abs(twice);
}

// Exact area of pixel (i, j) inside a convex polygon: the pixel square clipped by its edges.
double polygonCoverage(const Polygon& convex, int i, int j) {
  Polygon pixel = {
      {double(i), double(j)}, {i + 1.0, double(j)}, {i + 1.0, j + 1.0}, {double(i), j + 1.0}};
  core::Vec2 centroid{0.0, 0.0};
  for (const core::Vec2& p : convex) centroid += p / static_cast<double>(convex.size());
  for (std::size_t k = 0; k < convex.size() && !pixel.empty(); ++k) {
    const core::Vec2 a = convex[k], b = convex[(k + 1) % convex.size()];
    core::Vec2 n{a.y() - b.y(), b.x() - a.x()};
    if ((centroid - a).dot(n) < 0.0) n = -n;
    pixel = clip(pixel, a, n);
  }
  return pixel.size() < 3 ? 0.0 : area(pixel);
}

// Area of pixel (i, j) inside the disk: the length of each vertical chord inside the pixel,
// integrated across the pixel by the midpoint rule with 4000 steps (error below 1e-4).
double diskCoverage(const core::Vec2& c, double r, int i, int j) {
  constexpr int kSteps = 4000;
  // Wholly outside (the pixel's nearest point is beyond r) or inside (its farthest corner within
  // r).
  const double near_x = std::clamp(c.x(), double(i), i + 1.0) - c.x();
  const double near_y = std::clamp(c.y(), double(j), j + 1.0) - c.y();
  if (std::hypot(near_x, near_y) >= r) return 0.0;
  const double far_x = std::max(std::abs(i - c.x()), std::abs(i + 1.0 - c.x()));
  const double far_y = std::max(std::abs(j - c.y()), std::abs(j + 1.0 - c.y()));
  if (std::hypot(far_x, far_y) <= r) return 1.0;
  double sum = 0.0;
  for (int k = 0; k < kSteps; ++k) {
    const double x = i + (k + 0.5) / kSteps, dx = x - c.x();
    if (std::abs(dx) >= r) continue;
    const double half = std::sqrt(r * r - dx * dx);
    sum += std::max(0.0, std::min(j + 1.0, c.y() + half) - std::max(double(j), c.y() - half));
  }
  return sum / kSteps;
}

struct CoverageError {
  double max = 0.0, mean = 0.0;
  int edge_pixels = 0;  // pixels the shape covers only partly
};

class CoverageGLTest : public ::testing::Test {
 protected:
  std::unique_ptr<GlContext> context = createContext(defaultBackend());
  FontSet fonts{textFontsFor(defaultFontPath(), "en")};
  GlyphAtlas atlas{fonts};
  TextPainter painter{atlas};
  MeshCanvas canvas{painter};

  // Draws what `add` puts on the canvas in white on black and compares every pixel's red level
  // with `exact`.
  CoverageError measure(const std::function<void(ShapeSink&)>& add,
                        const std::function<double(int, int)>& exact) {
    context->makeCurrent();
    canvas.clear();
    canvas.beginBatch();
    add(canvas.shapes());
    canvas.finish();
    Framebuffers framebuffers(kSize, kSize);
    CanvasPainter canvas_painter(atlas);
    framebuffers.bindForDrawing();
    canvas_painter.paint(canvas, kSize, kSize, kBlack);
    std::vector<std::uint8_t> pixels;
    framebuffers.read(pixels);  // bottom row first

    CoverageError error;
    double sum = 0.0;
    for (int j = 0; j < kSize; ++j) {
      for (int i = 0; i < kSize; ++i) {
        const double expected = exact(i, j);
        const double drawn =
            pixels[(static_cast<std::size_t>(kSize - 1 - j) * kSize + i) * 4] / 255.0;
        const double e = std::abs(drawn - expected);
        error.max = std::max(error.max, e);
        if (expected > 1e-9 && expected < 1.0 - 1e-9) {
          ++error.edge_pixels;
          sum += e;
        } else {
          // Wholly inside or outside: right to one level of 8 bits (a pixel touching a corner
          // may get a trace of coverage from the product of its two edges).
          EXPECT_LE(e, 1.0 / 255.0 + 1e-9) << "pixel " << i << "," << j;
        }
      }
    }
    error.mean = error.edge_pixels > 0 ? sum / error.edge_pixels : 0.0;
    std::printf("coverage error: max %.4f, mean %.4f over %d edge pixels\n", error.max, error.mean,
                error.edge_pixels);
    return error;
  }
};

TEST_F(CoverageGLTest, DiskEdgesMatchExactAreaCoverage) {
  for (const auto& disk :
       {std::pair{core::Vec2{31.3, 30.7}, 19.6}, std::pair{core::Vec2{20.5, 40.2}, 6.35},
        std::pair{core::Vec2{40.0, 12.0}, 2.3}}) {
    // Named copies, not a structured binding: clang before 16 cannot capture bindings in lambdas.
    const core::Vec2 c = disk.first;
    const double r = disk.second;
    const CoverageError error = measure([&](ShapeSink& mesh) { mesh.addDisk(c, r, kWhite); },
                                        [&](int i, int j) { return diskCoverage(c, r, i, j); });
    EXPECT_GT(error.edge_pixels, 4 * r) << "radius " << r;  // the test saw the edge
    EXPECT_LE(error.max, 0.1) << "radius " << r;
    EXPECT_LE(error.mean, 0.02) << "radius " << r;
  }
}

TEST_F(CoverageGLTest, RotatedBlockEdgesMatchExactAreaCoverage) {
  for (double degrees : {0.0, 10.0, 30.0, 45.0, 71.0}) {
    const double angle = degrees * std::numbers::pi / 180.0;
    const core::Vec2 c{32.4, 31.7}, u{std::cos(angle), std::sin(angle)}, v{-u.y(), u.x()};
    const double half_u = 17.3, half_v = 9.6;
    const Polygon block = {c - half_u * u - half_v * v, c + half_u * u - half_v * v,
                           c + half_u * u + half_v * v, c - half_u * u + half_v * v};
    // The block as a thick line along u: the renderer's rotated box.
    const CoverageError error = measure(
        [&](ShapeSink& mesh) {
          mesh.addLine(c - half_u * u, c + half_u * u, 2.0 * half_v, kWhite);
        },
        [&](int i, int j) { return polygonCoverage(block, i, j); });
    EXPECT_GT(error.edge_pixels, 2.0 * (half_u + half_v)) << degrees << " degrees";
    EXPECT_LE(error.max, 0.1) << degrees << " degrees";
    EXPECT_LE(error.mean, 0.02) << degrees << " degrees";
  }
}

TEST_F(CoverageGLTest, ThinLineAndArrowHeadStayWithinATenth) {
  // A hairline (both edges inside one pixel) and an arrow (shaft and head meet without a seam).
  const core::Vec2 a{5.2, 50.3}, b{58.7, 20.1};
  const core::Vec2 u = (b - a).normalized(), v{-u.y(), u.x()};
  const double half = 0.35;
  const Polygon line = {a - half * v, b - half * v, b + half * v, a + half * v};
  const CoverageError hairline =
      measure([&](ShapeSink& mesh) { mesh.addLine(a, b, 2.0 * half, kWhite); },
              [&](int i, int j) { return polygonCoverage(line, i, j); });
  EXPECT_LE(hairline.max, 0.1);
  EXPECT_LE(hairline.mean, 0.02);

  const core::Vec2 tail{6.3, 40.6}, along = core::Vec2{1.0, -0.4}.normalized();
  const core::Vec2 across{-along.y(), along.x()};
  const double length = 50.0, shaft = 5.0, head_length = 16.0, head_width = 18.0;
  const core::Vec2 base = tail + (length - head_length) * along, tip = tail + length * along;
  const Polygon shaft_box = {tail - 0.5 * shaft * across, base - 0.5 * shaft * across,
                             base + 0.5 * shaft * across, tail + 0.5 * shaft * across};
  const Polygon head = {base - 0.5 * head_width * across, tip, base + 0.5 * head_width * across};
  const CoverageError arrow = measure(
      [&](ShapeSink& mesh) {
        mesh.addArrow(tail, along, length, shaft, head_length, head_width, kWhite);
      },
      [&](int i, int j) {
        return std::min(1.0, polygonCoverage(shaft_box, i, j) + polygonCoverage(head, i, j));
      });
  EXPECT_LE(arrow.max, 0.1);
  EXPECT_LE(arrow.mean, 0.02);
}

}  // namespace
}  // namespace collide::render
