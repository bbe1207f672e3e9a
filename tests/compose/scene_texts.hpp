#pragma once
// The lines of text a placed panel shows in its scene, as boxes in frame pixels with the leader
// line the painter draws from each (from the box's point nearest the leader's end,
// render/draw/draw_world_labels.cpp): the bodies' mass labels, readouts and numbers beside them,
// the dimensions' texts and notes, the legend's lines. Gathering them checks that each box is the
// text's real extent and that what a text refers to is there to be read.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "frame/frame_model.hpp"
#include "frame/layout.hpp"
#include "pixel_distances.hpp"
#include "render/text/text_metrics.hpp"

namespace collide::compose_test {

struct SceneText {
  Box box;
  std::string text;
  std::optional<std::size_t> body;  // the body it names (none: a dimension's text, the legend's)
  bool velocity = false;
  std::optional<core::Vec2> leader_from, leader_to;
};

// Appends the panel's texts to `texts`, adding a gtest failure (fatal where the model is
// inconsistent: a label without a place, a legend line naming no body) for each that is not what
// the painter would draw. `text_floor_px`: a printed figure's (frame::printTextFloorPx), 0 on a
// screen.
void gatherSceneTexts(const frame::PanelModel& panel, const frame::FrameLayout& layout,
                      const frame::WorldToPixel& to_px, render::TextMetrics& metrics,
                      double text_floor_px, std::vector<SceneText>& texts);

}  // namespace collide::compose_test
