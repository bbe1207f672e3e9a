// CPU tessellation, no GL.
#include "render/mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "frame_models.hpp"
#include "render/frame_mesh.hpp"

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
  resting.bodies[0].velocity_mps = {0.5 * kRestSpeed_mps, 0.0};
  const FrameLayout layout = computeFrameLayout(320, 180);
  MeshBuilder a, b;
  const FrameMeshRanges with = buildFrameMesh(moving, layout, a);
  const FrameMeshRanges without = buildFrameMesh(resting, layout, b);
  EXPECT_EQ(with.world_vertices - without.world_vertices, 9u);  // shaft quad + head triangle
}

}  // namespace
}  // namespace collide::render
