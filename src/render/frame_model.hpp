#pragma once
// What to draw in one frame, as plain data. Built by the app from a physics snapshot; the renderer
// never sees physics types. World coordinates are metres; the renderer maps them to pixels.
#include <string>
#include <vector>

#include "core/vec.hpp"

namespace collide::render {

struct Rgba {
  float r = 0.0f, g = 0.0f, b = 0.0f, a = 1.0f;  // each in [0, 1], straight alpha
};

enum class BodyShape { kRectangle, kDisk };

struct BodyModel {
  BodyShape shape = BodyShape::kRectangle;
  core::Vec2 center_m = {0.0, 0.0};
  core::Vec2 half_extent_m = {0.25, 0.25};  // rectangle: half width, half height; disk: radius in x
  Rgba fill;
  core::Vec2 velocity_mps = {0.0, 0.0};     // drawn as an arrow from above the body; none at rest
};

struct EnergySegment {
  double energy_J = 0.0;  // length of this segment in the bar's energy units
  Rgba color;
  std::string label;      // e.g. "KE1", "lost"; drawn once text rendering exists
};

// One horizontal bar whose full length stands for full_scale_J; segments are laid left to right.
struct EnergyBar {
  std::vector<EnergySegment> segments;
  double full_scale_J = 1.0;  // > 0: the initial total kinetic energy
};

// The rectangle of the world shown in the scene area; the renderer keeps metres square (uniform
// scale) and centres this window.
struct ViewWindow {
  core::Vec2 min_m = {-4.0, -1.0};
  core::Vec2 max_m = {4.0, 1.0};
};

struct FrameModel {
  Rgba background = {1.0f, 1.0f, 1.0f, 1.0f};
  ViewWindow view;
  bool draw_track = true;         // 1D scenes: the line the blocks slide on, at y = track_y_m
  double track_y_m = 0.0;
  std::vector<BodyModel> bodies;
  double arrow_m_per_mps = 0.25;  // arrow length in world metres per m/s of speed
  EnergyBar energy_bar;
};

}  // namespace collide::render
