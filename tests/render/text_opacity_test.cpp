// SPDX-License-Identifier: MIT
// Texts fading in or out (frame::PlacedText::opacity) without GL: the layout's items say how
// solid each is drawn (render::drawnItems, `collide layout`'s), and an SVG figure draws them with
// that opacity; a text at opacity 0 is neither listed nor drawn.
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "frame_models.hpp"
#include "render/frame_layout.hpp"
#include "render/vector/vector_painter.hpp"
#include "svg_shapes.hpp"

namespace collide::render {
namespace {

constexpr int kFigureWidthPx = 1280;
constexpr int kFigureHeightPx = 720;
constexpr float kFigureLabelOpacity = 0.5f;
constexpr float kFigureLegendOpacity = 0.25f;
constexpr float kFigureTagOpacity = 0.75f;

const frame::DrawnItem* itemNamed(const std::vector<frame::DrawnItem>& items,
                                  const std::string& id) {
  for (const frame::DrawnItem& item : items) {
    if (item.id == id) return &item;
  }
  return nullptr;
}

TEST(TextOpacityTest, TheLayoutSaysHowSolidEachTextIsDrawn) {
  frame::FrameModel frame = testing::fadingLabels(kFigureWidthPx, kFigureHeightPx,
                                                  kFigureLabelOpacity, kFigureLegendOpacity);
  // The block's number inside it, fading too (BodyModel::tag_opacity).
  frame.panels[0].bodies[0].tag = "1";
  frame.panels[0].bodies[0].tag_opacity = kFigureTagOpacity;
  const std::vector<frame::DrawnItem> items = drawnItems(frame, kFigureWidthPx, kFigureHeightPx);
  const struct {
    const char* id;
    float opacity;
  } expected[] = {{"mass.1", kFigureLabelOpacity},
                  {"leader.mass.1", kFigureLabelOpacity},
                  {"legend.velocity.1", kFigureLegendOpacity},
                  {"tag.1", kFigureTagOpacity},
                  {"body.1", 1.0f}};
  for (const auto& [id, opacity] : expected) {
    const frame::DrawnItem* item = itemNamed(items, id);
    ASSERT_NE(item, nullptr) << id;
    EXPECT_EQ(item->opacity, double(opacity)) << id;
  }
  // Nothing else fades.
  for (const frame::DrawnItem& item : items) {
    bool fading = false;
    for (const auto& [id, opacity] : expected) fading = fading || (item.id == id && opacity < 1.0f);
    if (!fading) {
      EXPECT_EQ(item.opacity, 1.0) << item.id;
    }
  }
}

TEST(TextOpacityTest, ATextAtOpacityZeroIsNotListed) {
  const std::vector<frame::DrawnItem> items =
      drawnItems(testing::fadingLabels(kFigureWidthPx, kFigureHeightPx, 0.0f, 0.0f), kFigureWidthPx,
                 kFigureHeightPx);
  for (const char* id : {"mass.1", "leader.mass.1", "legend.velocity.1"}) {
    EXPECT_EQ(itemNamed(items, id), nullptr) << id;
  }
  EXPECT_NE(itemNamed(items, "body.1"), nullptr);
}

collide::test::SvgDocument svgOf(const frame::FrameModel& frame) {
  VectorFigureOptions options;
  options.format = VectorFormat::kSvg;
  options.width_px = kFigureWidthPx;
  options.height_px = kFigureHeightPx;
  std::optional<collide::test::SvgDocument> svg =
      collide::test::readSvg(paintVectorFigure(frame, options));
  if (!svg) return {};
  return *svg;
}

const collide::test::SvgText* textHolding(const collide::test::SvgDocument& svg,
                                          const std::string& content) {
  for (const collide::test::SvgText& text : svg.texts) {
    if (text.content == content) return &text;
  }
  return nullptr;
}

// The stroked paths in `color` (the leader's: nothing else here is drawn in the muted colour).
std::vector<collide::test::SvgShape> strokedIn(const collide::test::SvgDocument& svg,
                                               const frame::Rgba& color) {
  std::vector<collide::test::SvgShape> found;
  for (const collide::test::SvgShape& shape : svg.shapes) {
    if (shape.stroke && collide::test::sameColor(*shape.stroke, color.r, color.g, color.b)) {
      found.push_back(shape);
    }
  }
  return found;
}

TEST(TextOpacityTest, AnSvgFigureDrawsFadingTextsWithTheirOpacity) {
  const frame::FrameModel solid =
      testing::fadingLabels(kFigureWidthPx, kFigureHeightPx, 1.0f, 1.0f);
  const frame::FrameModel faded = testing::fadingLabels(kFigureWidthPx, kFigureHeightPx,
                                                        kFigureLabelOpacity, kFigureLegendOpacity);
  const std::string& label = solid.panels[0].bodies[0].label;
  const std::string& legend = solid.panels[0].legend.entries[0].text;
  const frame::Rgba& muted = solid.style.muted_text;
  const struct {
    const frame::FrameModel* frame;
    double label, legend;
  } cases[] = {{&solid, 1.0, 1.0}, {&faded, kFigureLabelOpacity, kFigureLegendOpacity}};
  for (const auto& c : cases) {
    const collide::test::SvgDocument svg = svgOf(*c.frame);
    const collide::test::SvgText* label_text = textHolding(svg, label);
    const collide::test::SvgText* legend_text = textHolding(svg, legend);
    ASSERT_NE(label_text, nullptr);
    ASSERT_NE(legend_text, nullptr);
    // The style's text colour, 0.1 of full scale: 25.5 of 255, to the nearest 8-bit step.
    EXPECT_EQ(label_text->fill, "#1a1a1a");
    EXPECT_EQ(label_text->fill_opacity, c.label);
    EXPECT_EQ(legend_text->fill_opacity, c.legend);
    const std::vector<collide::test::SvgShape> leaders = strokedIn(svg, muted);
    ASSERT_EQ(leaders.size(), 1u);
    EXPECT_EQ(leaders[0].stroke_opacity, c.label);
  }
  const collide::test::SvgDocument gone =
      svgOf(testing::fadingLabels(kFigureWidthPx, kFigureHeightPx, 0.0f, 0.0f));
  EXPECT_EQ(textHolding(gone, label), nullptr);
  EXPECT_EQ(textHolding(gone, legend), nullptr);
  EXPECT_TRUE(strokedIn(gone, muted).empty());
}

}  // namespace
}  // namespace collide::render
