// SPDX-License-Identifier: MIT
#pragma once
// What the painters drew in a frame, item by item, in pixels: the frame's layout as the picture
// shows it (`collide layout --json`). Recorded while the frame is laid out for painting
// (render/frame_layout.hpp), never computed apart from it, so it is the truth about the picture.
#include <optional>
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "frame/layout.hpp"

namespace collide::frame {

// How a velocity arrow is drawn against the picture's scale.
enum class ArrowDrawn {
  kOnScale,     // its length is its speed at the scale
  kOffScale,    // too long for the frame: drawn shorter, with a break in its shaft
  kBelowScale,  // too short to read: drawn at a visible minimum
};

struct DrawnArrow {
  core::Vec2 from_px = {0.0, 0.0};  // the tail
  core::Vec2 to_px = {0.0, 0.0};    // the tip
  double value_mps = 0.0;           // the speed it stands for
  double scale_px_per_mps = 0.0;    // the picture's scale
  ArrowDrawn drawn = ArrowDrawn::kOnScale;
};

// A calibration stick (render --calibration): its ends' centres, the length it stands for and the
// picture's scale, so that a test or an overlay checks one against the other.
struct DrawnStick {
  core::Vec2 from_px = {0.0, 0.0};
  core::Vec2 to_px = {0.0, 0.0};
  double length_m = 0.0;
  double px_per_m = 0.0;  // the panel's scale: metres of the world to pixels
};

struct DrawnItem {
  // Stable for the same thing from frame to frame: "body.2", "velocity.2", "mass.1", "arrow.2",
  // "legend.velocity.3", "title", "caption"; in a comparison grid, a panel after the first
  // prefixes its items' ids with "panelN." (N from 1).
  std::string id;
  // body, label (a mass label, a body's number), readout (a velocity readout, the time, the info
  // line, an energy label), arrow, wall, legend, title, caption, scale (the scale arrow, the
  // ruler, the calibration stick and the origin), flash, inset (the momentum diagram), dimension,
  // chart.
  std::string kind;
  std::vector<std::string> lines;  // the text drawn, one entry per line; empty: none
  PixelRect box;                   // everything drawn for it, inside its clip
  int body = -1;                   // index into its panel's bodies; -1: none
  int panel = -1;                  // index into FrameModel::panels; -1: not in a panel
  std::optional<DrawnArrow> arrow;
  std::optional<DrawnStick> stick;
  // A leader's line, from its start (under its bar segment) to its end (on its entry).
  std::vector<core::Vec2> path;
  // 1: solid; less: a text fading in or out (frame::PlacedText::opacity).
  double opacity = 1.0;
};

}  // namespace collide::frame
