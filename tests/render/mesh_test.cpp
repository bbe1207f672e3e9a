// CPU tessellation, no GL.
#include "render/mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "frame_models.hpp"
#include "render/canvas.hpp"
#include "render/font.hpp"
#include "render/frame_drawing.hpp"
#include "render/renderer.hpp"

namespace collide::render {
namespace {

double triangleArea(const Vertex& a, const Vertex& b, const Vertex& c) {
  return 0.5 *
         std::abs((b.x_px - a.x_px) * (c.y_px - a.y_px) - (c.x_px - a.x_px) * (b.y_px - a.y_px));
}

double meshArea(const MeshBuilder& mesh) {
  double area = 0.0;
  const auto& v = mesh.vertices();
  for (std::size_t i = 0; i + 2 < v.size(); i += 3) area += triangleArea(v[i], v[i + 1], v[i + 2]);
  return area;
}

TEST(MeshTest, CircleSegmentsKeepDisksRoundAtAnySize) {
  EXPECT_EQ(circleSegments(0.1), 16);
  for (double radius : {5.0, 50.0, 500.0}) {
    const int n = circleSegments(radius);
    // Sagitta of one chord: how far the polygon strays inside the circle.
    const double sagitta = radius * (1.0 - std::cos(std::numbers::pi / n));
    EXPECT_LE(sagitta, 0.2 + 1e-9) << radius;
  }
  EXPECT_LE(circleSegments(1e6), 1024);
}

TEST(MeshTest, FrameAndFillTileTheRectangleWithoutOverlap) {
  MeshBuilder mesh;
  mesh.addRectFrame({0.0, 0.0, 20.0, 10.0}, 2.0, {});
  EXPECT_NEAR(meshArea(mesh), 200.0 - 16.0 * 6.0, 1e-9);
}

TEST(MeshTest, RingAndDiskAreasMatchCircles) {
  // The polygon loses at most (0.2 px sagitta) × perimeter of area per circle.
  const double pi = std::numbers::pi;
  MeshBuilder disk;
  disk.addDisk({0.0, 0.0}, 100.0, {});
  EXPECT_NEAR(meshArea(disk), pi * 100.0 * 100.0, 0.2 * 2.0 * pi * 100.0);
  MeshBuilder ring;
  ring.addRing({0.0, 0.0}, 100.0, 90.0, {});
  EXPECT_NEAR(meshArea(ring), pi * (100.0 * 100.0 - 90.0 * 90.0), 0.2 * 2.0 * pi * 190.0);
}

TEST(MeshTest, ArrowPointsAlongItsDirectionWithRequestedLength) {
  MeshBuilder mesh;
  mesh.addArrow({10.0, 10.0}, {0.0, -1.0}, 30.0, 2.0, 8.0, 6.0, {});
  float min_y = 1e9f;
  for (const Vertex& v : mesh.vertices()) min_y = std::min(min_y, v.y_px);
  EXPECT_FLOAT_EQ(min_y, -20.0f);  // tip 30 px up from the tail
}

TEST(MeshTest, BodyAtRestGetsNoArrowTriangles) {
  FrameModel moving = testing::twoBlocks();
  FrameModel resting = moving;
  resting.panels[0].bodies[0].velocity_mps = {0.5 * kRestSpeed_mps, 0.0};
  const FrameLayout layout = computeFrameLayout(320, 180);
  Font font(defaultFontPath());
  GlyphAtlas atlas(font);
  TextPainter painter(atlas);
  Canvas a(painter), b(painter);
  drawFrame(moving, layout, a);
  drawFrame(resting, layout, b);
  // Batch 0: header; batch 1: the panel's world.
  ASSERT_GE(a.batches().size(), 2u);
  EXPECT_TRUE(a.batches()[1].clip.has_value());
  EXPECT_EQ(a.batches()[1].shape_count - b.batches()[1].shape_count,
            9u);  // shaft quad + head triangle
}

TEST(MeshTest, DashedPolylineDrawsHalfItsLength) {
  MeshBuilder solid, dashed;
  const std::vector<core::Vec2> path = {{0.0, 0.0}, {30.0, 0.0}, {30.0, 50.0}};
  solid.addPolyline(path, 2.0, {});
  dashed.addPolyline(path, 2.0, {}, 5.0);
  EXPECT_NEAR(meshArea(solid), 160.0, 1e-9);
  EXPECT_NEAR(meshArea(dashed), 80.0, 1e-9);
}

TEST(MeshTest, SectorIsAQuarterOfTheDisk) {
  MeshBuilder quarter;
  quarter.addSector({0.0, 0.0}, 100.0, 0.0, 0.5 * std::numbers::pi, {});
  EXPECT_NEAR(meshArea(quarter), 0.25 * std::numbers::pi * 1e4, 0.2 * 0.5 * std::numbers::pi * 100);
}

}  // namespace
}  // namespace collide::render
