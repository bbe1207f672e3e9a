// The momentum diagram on the principles, checked on the frame description: it has a
// place of its own that never covers the scene (the world's area keeps clear of it, so no body
// or label is under it), its one scale for the whole picture holds every instant's chain inside
// its plot and fills it, and it states that scale (a bar of a round momentum, labelled with its
// value and unit, as long as that momentum's arrow would be). billiards-glancing (2D, the preset
// that shows it) and worked-example with the diagram switched on (1D), at 1280x720 and 640x360,
// at 13 instants.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include "app/animation.hpp"
#include "frame_layouts.hpp"
#include "pixel_rects.hpp"
#include "round_numbers.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

using test::inside;
using test::isRound;
using test::overlaps;

class MomentumDiagramTest : public ::testing::TestWithParam<test::PictureSize> {};

TEST_P(MomentumDiagramTest, BesideTheSceneFittedToItsBoxWithItsOwnStatedScale) {
  const auto [width_px, height_px] = GetParam();
  scene::SceneDesc one_d = scene::loadPreset("worked-example");
  one_d.view.momentum_diagram = true;
  render::TextMetrics metrics;
  for (const scene::SceneDesc& scene : {scene::loadPreset("billiards-glancing"), one_d}) {
    ASSERT_TRUE(scene.view.momentum_diagram) << scene.name;
    const app::Animation animation = app::animate(scene, {width_px, height_px});
    const double end = animation.frames.simulatedDuration_s();
    for (int k = 0; k <= 12; ++k) {
      const double t = end * k / 12.0;
      SCOPED_TRACE(scene.name + " at t = " + std::to_string(t) + " s");
      const frame::FrameModel frame = animation.frames.frameAtSimulated(t);
      const frame::FrameLayout layout = test::layoutMeasured(frame, width_px, height_px, metrics);
      const frame::PanelModel& panel = frame.panels.front();
      const frame::PanelLayout& where = layout.panels.front();
      ASSERT_TRUE(panel.momentum.has_value());
      const std::optional<frame::PixelRect> box = frame::momentumBox(panel, where, layout);
      ASSERT_TRUE(box.has_value()) << "no diagram drawn";
      EXPECT_TRUE(inside(*box, {0.0, 0.0, double(width_px), double(height_px)}, 0.0));

      // Beside the world, so nothing of the scene is under it.
      const frame::PixelRect world = frame::worldArea(panel, where, layout);
      EXPECT_FALSE(overlaps(world, *box)) << "the world reaches under the diagram";
      const frame::WorldToPixel to_px = frame::fitView(panel.view, world);
      for (const frame::BodyModel& body : panel.bodies) {
        const core::Vec2 c = to_px.toPixel(body.center_m);
        const double hx = to_px.px_per_m * body.half_extent_m.x();
        const double hy =
            body.shape == frame::BodyShape::kDisk ? hx : to_px.px_per_m * body.half_extent_m.y();
        EXPECT_FALSE(overlaps({c.x() - hx, c.y() - hy, c.x() + hx, c.y() + hy}, *box))
            << body.label << " under the diagram";
        for (const auto& placed : {body.label_at, body.velocity_label_at}) {
          if (!placed) continue;
          const frame::PixelRect text{placed->top_left_px.x(), placed->top_left_px.y(),
                                      placed->top_left_px.x() + placed->size_px.x(),
                                      placed->top_left_px.y() + placed->size_px.y()};
          EXPECT_FALSE(overlaps(text, *box)) << "a label under the diagram";
        }
      }

      // One scale for the run: this instant's chain (0, p₁, p₁ + p₂, ...) from the scene's
      // masses and the drawn velocities lies in the plot, which is inside the box.
      const frame::MomentumDiagram& diagram = *panel.momentum;
      const frame::MomentumChainPlot plot = frame::momentumChainPlot(diagram, *box, layout);
      EXPECT_TRUE(inside(plot.area, *box, 0.0));
      ASSERT_EQ(diagram.arrows.size(), scene.bodies.size());
      core::Vec2 chain{0.0, 0.0};
      const double slack_px = 1e-6 * plot.area.width();
      for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        chain += scene.bodies[i].mass_kg * panel.bodies[i].velocity_mps;
        const core::Vec2 p = plot.start_px + plot.px_per_Ns * core::Vec2{chain.x(), -chain.y()};
        EXPECT_GE(p.x(), plot.area.x0 - slack_px);
        EXPECT_LE(p.x(), plot.area.x1 + slack_px);
        if (plot.one_d) continue;  // a staircase: rows of its own
        EXPECT_GE(p.y(), plot.area.y0 - slack_px);
        EXPECT_LE(p.y(), plot.area.y1 + slack_px);
      }
      // Fitted: the chain's reach over the run spans the plot in one direction.
      const core::Vec2 reach = diagram.reach_high_Ns - diagram.reach_low_Ns;
      const double fill =
          std::max(reach.x() * plot.px_per_Ns / plot.area.width(),
                   plot.one_d ? 0.0 : reach.y() * plot.px_per_Ns / plot.area.height());
      EXPECT_NEAR(fill, 1.0, 1e-9);

      // Its scale stated: a round momentum with its unit, the number its label says, drawn as
      // long as that momentum's arrow (px_per_Ns per kg·m/s), the bar and its label in the box.
      ASSERT_GT(diagram.scale_bar_Ns, 0.0);
      EXPECT_TRUE(isRound(diagram.scale_bar_Ns)) << diagram.scale_bar_Ns;
      EXPECT_LE(diagram.scale_bar_Ns, reach.maxCoeff());
      const std::string unit = " kg\u00b7m/s";
      const std::string& label = diagram.scale_bar_label;
      ASSERT_GT(label.size(), unit.size());
      ASSERT_EQ(label.substr(label.size() - unit.size()), unit);
      EXPECT_DOUBLE_EQ(std::stod(label.substr(0, label.size() - unit.size())),
                       diagram.scale_bar_Ns);
      EXPECT_NEAR(plot.scale_bar_px / diagram.scale_bar_Ns, plot.px_per_Ns, 1e-9 * plot.px_per_Ns);
      const double pad = 0.5 * layout.small_px;
      EXPECT_LE(box->x0 + pad + plot.scale_bar_px + pad + metrics.width(label, layout.small_px),
                box->x1 - pad + 1e-9)
          << label << " does not fit beside its bar";
      EXPECT_GE(plot.scale_bar_y_px, plot.area.y1);
      EXPECT_LE(plot.scale_bar_y_px, box->y1);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Sizes, MomentumDiagramTest, test::videoSizes(), test::sizeName);

}  // namespace
}  // namespace collide
