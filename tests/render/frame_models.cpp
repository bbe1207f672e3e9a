#include "frame_models.hpp"

#include "frame/layout.hpp"

namespace collide::render::testing {

frame::FrameModel twoBlocks() {
  frame::FrameModel frame;
  frame::PanelModel panel;
  panel.view = {{-4.0, 0.0}, {4.0, 0.7}};
  panel.track_y_m = 0.0;
  frame::BodyModel left;
  left.center_m = {-2.0, 0.25};
  left.half_extent_m = {0.25, 0.25};
  left.fill = kBlue;
  left.velocity_mps = {1.5, 0.0};
  frame::BodyModel right;
  right.center_m = {1.0, 0.35};
  right.half_extent_m = {0.35, 0.35};
  right.fill = kOrange;
  right.velocity_mps = {-0.5, 0.0};
  panel.bodies = {left, right};
  panel.arrow_m_per_mps = 0.5;
  panel.energy_bar.full_scale_J = 1.0;
  panel.energy_bar.segments = {{0.45, kBlue, ""}, {0.30, kOrange, ""}, {0.15, kGray, ""}};
  frame.panels = {panel};
  return frame;
}

frame::FrameModel diskAndTranslucent() {
  frame::FrameModel frame;
  frame::PanelModel panel;
  panel.view = {{-2.0, -1.0}, {2.0, 1.0}};
  panel.draw_track = false;
  panel.two_d = true;
  frame::BodyModel disk;
  disk.shape = frame::BodyShape::kDisk;
  disk.center_m = {-0.5, -0.1};
  disk.half_extent_m = {0.6, 0.6};
  disk.fill = kBlue;
  disk.velocity_mps = {0.8, 0.6};
  frame::BodyModel glass;
  glass.center_m = {0.1, -0.3};
  glass.half_extent_m = {0.4, 0.3};
  glass.fill = {1.0f, 0.5f, 0.05f, 0.5f};
  glass.velocity_mps = {-0.7, 0.3};
  frame::BodyModel resting;
  resting.center_m = {1.4, 0.3};
  resting.half_extent_m = {0.2, 0.2};
  resting.fill = kGray;
  panel.bodies = {disk, glass, resting};
  panel.arrow_m_per_mps = 0.6;
  panel.energy_bar.full_scale_J = 2.0;
  panel.energy_bar.segments = {{1.2, kBlue, ""}, {0.8, kGray, ""}};
  frame.panels = {panel};
  return frame;
}

frame::FrameModel labelledBlocks() {
  frame::FrameModel frame = twoBlocks();
  frame.title = "Inelastic collision, e = 0.5";
  frame.time_readout = "t = 1.250 s";
  frame::PanelModel& panel = frame.panels[0];
  panel.info = "collisions: 1   Σp: before +1.00, now +1.00 kg·m/s";
  panel.ruler = true;
  panel.bodies[0].label = "m₁ = 1.00 kg";
  panel.bodies[0].velocity_label = "v₁′ = +1.50 m/s";
  panel.bodies[1].label = "m₂ = 2.00 kg";
  panel.bodies[1].velocity_label = "v₂′ = −0.50 m/s";
  panel.energy_bar.segments[0].label = "KE₁ 0.45 J";
  panel.energy_bar.segments[1].label = "KE₂ 0.30 J";
  panel.energy_bar.segments[2].label = "lost 0.15 J";
  panel.caption = "t = 1.250 s: v₁′ = +1.50 m/s, v₂′ = −0.50 m/s; lost 0.15 J (15.0%)";
  return frame;
}

frame::FrameModel twoDimensional() {
  frame::FrameModel frame;
  frame.title = "Glancing collision";
  frame.time_readout = "t = 0.800 s";
  frame::PanelModel panel;
  panel.two_d = true;
  panel.draw_track = false;
  panel.ruler = true;
  panel.view = {{-2.0, -1.0}, {2.0, 1.0}};
  panel.walls = {{{2.0, 0.0}, {-1.0, 0.0}}};
  const auto disk = [](core::Vec2 c, double r, frame::Rgba fill, core::Vec2 v) {
    frame::BodyModel b;
    b.shape = frame::BodyShape::kDisk;
    b.center_m = c;
    b.half_extent_m = {r, r};
    b.fill = fill;
    b.velocity_mps = v;
    return b;
  };
  frame::BodyModel a = disk({-1.0, 0.2}, 0.3, kBlue, {0.8, 0.5});
  a.label = "m₁ = 1.0 kg";
  a.velocity_label = "v₁′ = 0.94 m/s";
  a.trail_m = {{-1.8, -0.3}, {-1.6, -0.175}, {-1.4, -0.05}, {-1.2, 0.075}, {-1.0, 0.2}};
  a.tag = "1";
  frame::BodyModel b = disk({0.6, -0.3}, 0.25, kOrange, {0.4, -0.6});
  b.show_orientation = true;
  b.angle_rad = 0.7;
  b.tag = "2";
  frame::BodyModel c = disk({1.1, -0.3}, 0.25, kGray, {0.4, -0.6});
  panel.bodies = {a, b, c};
  panel.bonds = {{1, 2}};
  panel.flashes = {{{0.2, 0.0}, 0.7}};
  panel.center_of_mass_m = core::Vec2{0.1, -0.1};
  panel.arrow_m_per_mps = 0.8;
  frame::MomentumDiagram momentum;
  momentum.arrows = {{{0.8, 0.5}, kBlue, "p₁"}, {{0.4, -0.6}, kOrange, "p₂"}};
  momentum.full_scale_Ns = 1.3;
  // The chain's reach over a run (0, p₁, p₁ + p₂ here) and its stated scale, as compose sets them.
  momentum.reach_low_Ns = {0.0, -0.1};
  momentum.reach_high_Ns = {1.2, 0.5};
  momentum.scale_bar_Ns = 0.5;
  momentum.scale_bar_label = "0.5 kg·m/s";
  panel.momentum = momentum;
  panel.energy_bar.full_scale_J = 1.0;
  panel.energy_bar.segments = {{0.6, kBlue, "KE₁"}, {0.3, kOrange, "KE₂"}, {0.1, kGray, "lost"}};
  frame.panels = {panel};
  return frame;
}

frame::FrameModel fadingLabels(int width_px, int height_px, float label_opacity,
                               float legend_opacity) {
  frame::FrameModel frame;
  frame::PanelModel panel;
  panel.view = {{-4.0, 0.0}, {4.0, 0.7}};
  panel.draw_track = false;
  frame::BodyModel block;
  block.center_m = {-3.0, 0.25};
  block.half_extent_m = {0.25, 0.25};
  block.fill = kBlue;
  block.label = "m₁ = 1.00 kg";
  panel.bodies = {block};
  panel.energy_bar.full_scale_J = 1.0;
  frame.panels = {panel};
  // Placed where compose would place for this size: inside the scene's clip, clear of the block
  // (the left eighth of the view) and of each other.
  const frame::FrameLayout layout =
      frame::computeFrameLayout(width_px, height_px, frame::shapeOf(frame));
  const frame::PixelRect& clip = layout.panel().world_clip;
  frame::PanelModel& placed = frame.panels[0];
  placed.placed_for_width_px = width_px;
  placed.placed_for_height_px = height_px;
  placed.placed_for_scale_px = layout.scale_px;
  frame::PlacedText label;
  label.top_left_px = {clip.x0 + 0.45 * clip.width(), clip.y0 + 0.15 * clip.height()};
  label.size_px = {6.0 * layout.text_px, frame::kLineSpacing * layout.text_px};
  label.leader_to_px = core::Vec2{label.top_left_px.x() - 0.1 * clip.width(),
                                  label.top_left_px.y() + 0.5 * label.size_px.y()};
  label.opacity = label_opacity;
  placed.bodies[0].label_at = label;
  frame::ReadoutLegend::Entry entry;
  entry.body = 0;
  entry.text = "v₁ = 0.00 m/s";
  entry.top_left_px = {clip.x0 + 0.45 * clip.width(), clip.y0 + 0.6 * clip.height()};
  entry.opacity = legend_opacity;
  placed.legend.entries = {entry};
  return frame;
}

frame::FrameModel chartOnly() {
  frame::FrameModel frame;
  frame.title = "Energy";
  frame::ChartModel chart;
  chart.x_label = "t (s)";
  chart.y_label = "energy (J)";
  chart.min = {0.0, 0.0};
  chart.max = {4.0, 2.5};
  chart.series = {
      {"KE₁", kBlue, {{0.0, 2.0}, {1.2, 2.0}, {1.2, 0.3}, {4.0, 0.3}}, false},
      {"KE₂", kOrange, {{0.0, 0.5}, {1.2, 0.5}, {1.2, 1.2}, {4.0, 1.2}}, false},
      {"total", {0.1f, 0.1f, 0.1f, 1.0f}, {{0.0, 2.5}, {1.2, 2.5}, {1.2, 1.5}, {4.0, 1.5}}, true}};
  chart.cursor_x = 2.4;
  frame.charts = {chart};
  return frame;
}

}  // namespace collide::render::testing
