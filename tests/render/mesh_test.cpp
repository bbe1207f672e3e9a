// CPU tessellation, no GL.
#include "render/draw/mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "frame_models.hpp"
#include "render/draw/canvas.hpp"
#include "render/draw/frame_drawing.hpp"
#include "render/renderer.hpp"
#include "render/text/font_set.hpp"

namespace collide::render {
namespace {

// The quad a primitive is drawn over, as its bounding box.
frame::PixelRect quadBounds(const MeshBuilder& mesh, std::size_t shape) {
  frame::PixelRect box{1e30, 1e30, -1e30, -1e30};
  for (int k = 0; k < kVerticesPerShape; ++k) {
    const Vertex& v = mesh.vertices()[shape * kVerticesPerShape + k];
    box.x0 = std::min<double>(box.x0, v.x_px);
    box.y0 = std::min<double>(box.y0, v.y_px);
    box.x1 = std::max<double>(box.x1, v.x_px);
    box.y1 = std::max<double>(box.y1, v.y_px);
  }
  return box;
}

ShapeKind kindOf(const Vertex& v) {
  return static_cast<ShapeKind>(static_cast<int>(v.kind));
}

// Total length of the stroke segments in `mesh`.
double strokeLength(const MeshBuilder& mesh) {
  double length = 0.0;
  for (std::size_t i = 0; i < mesh.shapeCount(); ++i) {
    const Vertex& v = mesh.shape(i);
    if (kindOf(v) != ShapeKind::kStroke) continue;
    length += std::hypot(v.p0[2] - v.p0[0], v.p0[3] - v.p0[1]);
  }
  return length;
}

TEST(MeshTest, EveryShapeIsOneQuadReachingAPixelBeyondIt) {
  MeshBuilder mesh;
  mesh.addDisk({50.0, 40.0}, 10.0, {});
  ASSERT_EQ(mesh.shapeCount(), 1u);
  EXPECT_EQ(mesh.vertexCount(), 6u);
  const frame::PixelRect box = quadBounds(mesh, 0);
  EXPECT_NEAR(box.x0, 39.0, 1e-4);
  EXPECT_NEAR(box.x1, 61.0, 1e-4);
  EXPECT_NEAR(box.y0, 29.0, 1e-4);
  EXPECT_NEAR(box.y1, 51.0, 1e-4);
  EXPECT_EQ(kindOf(mesh.shape(0)), ShapeKind::kDisk);
  EXPECT_FLOAT_EQ(mesh.shape(0).p0[2], 10.0f);
  EXPECT_FLOAT_EQ(mesh.shape(0).p0[3], 0.0f);
}

TEST(MeshTest, FrameIsOneBoxWithItsThicknessAsInset) {
  MeshBuilder mesh;
  mesh.addRectFrame({0.0, 0.0, 20.0, 10.0}, 2.0, {});
  ASSERT_EQ(mesh.shapeCount(), 1u);
  const Vertex& v = mesh.shape(0);
  EXPECT_EQ(kindOf(v), ShapeKind::kBox);
  EXPECT_FLOAT_EQ(v.p1[0], 10.0f);
  EXPECT_FLOAT_EQ(v.p1[1], 5.0f);
  EXPECT_FLOAT_EQ(v.p1[2], 2.0f);
  // A frame thicker than half the rectangle is the whole rectangle.
  MeshBuilder thick;
  thick.addRectFrame({0.0, 0.0, 20.0, 10.0}, 8.0, {});
  EXPECT_FLOAT_EQ(thick.shape(0).p1[2], 5.0f);
}

TEST(MeshTest, RingKeepsBothRadiiAndDegenerateShapesAreDropped) {
  MeshBuilder mesh;
  mesh.addRing({0.0, 0.0}, 100.0, 90.0, {});
  ASSERT_EQ(mesh.shapeCount(), 1u);
  EXPECT_FLOAT_EQ(mesh.shape(0).p0[2], 100.0f);
  EXPECT_FLOAT_EQ(mesh.shape(0).p0[3], 90.0f);
  mesh.addRing({0.0, 0.0}, 90.0, 100.0, {});
  mesh.addDisk({0.0, 0.0}, 0.0, {});
  mesh.addLine({3.0, 3.0}, {3.0, 3.0}, 2.0, {});
  mesh.addTriangle({0.0, 0.0}, {1.0, 1.0}, {2.0, 2.0}, {});
  mesh.addRect({0.0, 0.0, 0.0, 5.0}, {});
  EXPECT_EQ(mesh.shapeCount(), 1u);
}

TEST(MeshTest, ArrowIsOnePrimitiveWhoseQuadReachesItsTip) {
  MeshBuilder mesh;
  mesh.addArrow({10.0, 10.0}, {0.0, -1.0}, 30.0, 2.0, 8.0, 6.0, {});
  ASSERT_EQ(mesh.shapeCount(), 1u);
  EXPECT_EQ(kindOf(mesh.shape(0)), ShapeKind::kArrow);
  const frame::PixelRect box = quadBounds(mesh, 0);
  EXPECT_NEAR(box.y0, -21.0, 1e-4);  // tip 30 px up from the tail, plus the margin
  EXPECT_NEAR(box.y1, 11.0, 1e-4);
  EXPECT_NEAR(box.x0, 6.0, 1e-4);  // half the head's width, plus the margin
  // A head longer than the arrow shrinks to the arrow's length.
  MeshBuilder short_arrow;
  short_arrow.addArrow({0.0, 0.0}, {1.0, 0.0}, 5.0, 2.0, 8.0, 6.0, {});
  EXPECT_FLOAT_EQ(short_arrow.shape(0).p1[2], 5.0f);
}

// An arrow too short to read against the scale (under_scale) is one "below scale" mark, the same
// in 1D and 2D: a bar across the base of a head, the head no longer than the layout's, beginning
// where its visible part begins (mark_from_px, a 2D body's edge), and never a dashed shaft: no
// arrow primitive longer than its head, no strokes, and one band, the bar, across the direction.
TEST(MeshTest, AnArrowBelowScaleIsOneMarkWithoutAShaft) {
  for (const double hidden_px : {0.0, 40.0}) {
    frame::ArrowShape shape;
    shape.under_scale = true;
    shape.head_length_px = 12.0;
    shape.head_width_px = 10.0;
    shape.shaft_px = 3.0;
    shape.length_px = hidden_px + shape.head_length_px;
    shape.mark_from_px = hidden_px;
    FontSet fonts(textFontsFor(defaultFontPath(), "en"));
    GlyphAtlas atlas(fonts);
    TextPainter painter(atlas);
    MeshCanvas canvas(painter);
    canvas.beginBatch();
    drawArrowShape({100.0, 50.0}, {1.0, 0.0}, shape, {}, canvas.shapes());
    canvas.finish();
    const std::vector<Vertex>& vertices = canvas.shapeVertices();
    int arrows = 0, bars = 0;
    for (std::size_t i = 0; i < vertices.size(); i += kVerticesPerShape) {
      const Vertex& v = vertices[i];
      if (kindOf(v) == ShapeKind::kArrow) {
        ++arrows;
        EXPECT_LE(v.p1[0], shape.head_length_px + 1e-4) << "an arrow with a shaft";
        EXPECT_GE(v.p0[0], 100.0 + hidden_px) << "the head starts under the body";
      } else if (kindOf(v) == ShapeKind::kBox) {  // a line: centre, unit axis, half extents
        ++bars;
        EXPECT_NEAR(v.p0[2], 0.0, 1e-4) << "a band along the arrow: a shaft";
        EXPECT_NEAR(v.p0[0], 100.0 + hidden_px, 1e-4) << "the bar not where the mark begins";
        EXPECT_GE(2.0 * v.p1[0], shape.head_width_px) << "a bar narrower than the head";
      } else {
        ADD_FAILURE() << "a shape of kind " << v.kind << " (a dashed shaft is strokes)";
      }
    }
    EXPECT_EQ(arrows, 1) << hidden_px;
    EXPECT_EQ(bars, 1) << hidden_px;
  }
}

TEST(MeshTest, PolylineSegmentsKnowTheirNeighbours) {
  MeshBuilder mesh;
  // The repeated point (a body at rest in a trail) is dropped with its zero-length segment.
  mesh.addPolyline({{0.0, 0.0}, {30.0, 0.0}, {30.0, 0.0}, {30.0, 50.0}}, 2.0,
                   std::vector<frame::Rgba>{{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}});
  ASSERT_EQ(mesh.shapeCount(), 2u);
  const Vertex& first = mesh.shape(0);
  const Vertex& second = mesh.shape(1);
  EXPECT_EQ(kindOf(first), ShapeKind::kStroke);
  EXPECT_FLOAT_EQ(first.p2[0], 1.0f);  // half the thickness
  EXPECT_FLOAT_EQ(first.p2[1], 0.0f);  // no previous segment
  EXPECT_FLOAT_EQ(first.p2[2], 1.0f);  // a next one, ending at (30, 50)
  EXPECT_FLOAT_EQ(first.p1[2], 30.0f);
  EXPECT_FLOAT_EQ(first.p1[3], 50.0f);
  EXPECT_FLOAT_EQ(second.p2[1], 1.0f);
  EXPECT_FLOAT_EQ(second.p2[2], 0.0f);
  EXPECT_FLOAT_EQ(second.p1[0], 0.0f);  // previous point
  EXPECT_FLOAT_EQ(first.r, 1.0f);
  EXPECT_FLOAT_EQ(second.b, 1.0f);  // the colour of the segment that reached (30, 50)
}

TEST(MeshTest, BodyAtRestGetsNoArrowTriangles) {
  frame::FrameModel moving = testing::twoBlocks();
  frame::FrameModel resting = moving;
  resting.panels[0].bodies[0].velocity_mps = {0.5 * kRestSpeed_mps, 0.0};
  const frame::FrameLayout layout = frame::computeFrameLayout(320, 180);
  FontSet fonts(textFontsFor(defaultFontPath(), "en"));
  GlyphAtlas atlas(fonts);
  TextPainter painter(atlas);
  MeshCanvas a(painter), b(painter);
  drawFrame(moving, layout, a);
  drawFrame(resting, layout, b);
  // Batch 0: header; batch 1: the panel's world.
  ASSERT_GE(a.batches().size(), 2u);
  EXPECT_TRUE(a.batches()[1].clip.has_value());
  EXPECT_EQ(a.batches()[1].shape_count - b.batches()[1].shape_count,
            static_cast<std::size_t>(kVerticesPerShape));  // one arrow primitive
}

// shape.frag reads p2.w in every program (so that all of them share one triangle set-up in
// llvmpipe) and relies on it being 0: a primitive with p2.w = 1 and parameters summing to 1 would
// vanish. Every kind of primitive, drawn from the fullest hand-built frames, keeps it 0.
TEST(MeshTest, EveryPrimitiveLeavesTheLastParameterZero) {
  FontSet fonts(textFontsFor(defaultFontPath(), "en"));
  GlyphAtlas atlas(fonts);
  TextPainter painter(atlas);
  bool seen[7] = {};
  for (const frame::FrameModel& frame : {testing::labelledBlocks(), testing::twoDimensional(),
                                         testing::chartOnly(), testing::diskAndTranslucent()}) {
    MeshCanvas canvas(painter);
    const frame::FrameLayout layout = frame::layoutFrame(
        frame, 640, 360, 0.0,
        [&](std::string_view text, double size) { return painter.width(text, size); });
    drawFrame(frame, layout, canvas);
    const std::vector<Vertex>& vertices = canvas.shapeVertices();
    ASSERT_FALSE(vertices.empty()) << frame.title;
    for (const Vertex& v : vertices) {
      EXPECT_EQ(v.p2[3], 0.0f);
      const int kind = static_cast<int>(kindOf(v));
      if (kind >= 1 && kind <= 6) seen[kind] = true;
    }
  }
  for (int kind = 1; kind <= 6; ++kind) EXPECT_TRUE(seen[kind]) << "no primitive of kind " << kind;
}

TEST(MeshTest, DashedPolylineDrawsHalfItsLength) {
  MeshBuilder solid, dashed;
  const std::vector<core::Vec2> path = {{0.0, 0.0}, {32.0, 0.0}, {32.0, 48.0}};
  solid.addPolyline(path, 2.0, frame::Rgba{});
  dashed.addPolyline(path, 2.0, frame::Rgba{}, 5.0);
  EXPECT_NEAR(strokeLength(solid), 80.0, 1e-4);
  EXPECT_NEAR(strokeLength(dashed), 40.0, 1e-4);
  // Dashes 0..5, 10..15, 20..25, 30..35 (turning the corner at 32, so two segments), 40..45, ...,
  // 70..75: 8 dashes, 9 segments.
  EXPECT_EQ(dashed.shapeCount(), 9u);
}

TEST(MeshTest, SectorsWiderThanAQuarterTurnAreCut) {
  const double pi = std::numbers::pi;
  MeshBuilder quarter, three_quarters;
  quarter.addSector({0.0, 0.0}, 100.0, 0.0, 0.5 * pi, {});
  three_quarters.addSector({0.0, 0.0}, 100.0, 0.0, 1.5 * pi, {});
  ASSERT_EQ(quarter.shapeCount(), 1u);
  EXPECT_NEAR(quarter.shape(0).p1[2], 0.0f, 1e-6);  // cos of the end angle
  EXPECT_NEAR(quarter.shape(0).p1[3], 1.0f, 1e-6);
  ASSERT_EQ(three_quarters.shapeCount(), 3u);
  EXPECT_NEAR(three_quarters.shape(2).p1[3], -1.0f, 1e-6);  // ends at 270 degrees
}

}  // namespace
}  // namespace collide::render
