// SPDX-License-Identifier: MIT
#pragma once
// The legend of a panel's labels (label_placement.cpp): where the readouts and mass labels that
// found no room by their bodies are listed, in a free place of the scene.
#include <vector>

#include "compose/label_arrangement.hpp"
#include "compose/label_candidates.hpp"
#include "frame/frame_model.hpp"
#include "frame/layout.hpp"
#include "text/text_measure.hpp"

namespace collide::compose {

// A panel as its labels are placed: where it stands in the frame, and its labels' text.
struct PanelText {
  frame::PanelModel& panel;
  const frame::PanelLayout& where;
  const frame::FrameLayout& layout;
  text::TextMeasure& metrics;
  double size_px;  // the labels' text size
  double line_px;  // the height of a line of it
};

// Lists in the panel's legend the labels that gave way by their bodies (`gives_way`) and, where
// a readout gave way by its arrow (`readout_gives_way`), every arrow's readout; the labels
// listed give way too (chosen -1, gives_way set). Where the legend finds no room among the
// labels placed, those move around it (`arrangement`); where it finds none at all, it lists
// fewer, then each text on two lines; where that too finds none, the panel has no legend.
// `staying`: readouts placed by their arrows that stay listed where the legend keeps its place
// (LabelSlot::legend), every arrow's readout with them; where it cannot, they stay by their arrows.
void listInLegend(std::vector<Label>& labels, LabelScene& scene, LabelArrangement& arrangement,
                  const PanelText& text, std::vector<bool>& gives_way, bool readout_gives_way,
                  const std::vector<bool>& staying);

}  // namespace collide::compose
