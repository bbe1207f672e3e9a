// SPDX-License-Identifier: MIT
#pragma once
// What a label's place costs in a frame, asked for any box: the layout over time
// (label_timeline.hpp) plans each label's way through a shot against the scene of each step and
// the ways of the labels planned before it, and asks here what a place there runs into. The
// scene and the candidate places are label placement's own (label_scene.hpp,
// label_candidates.hpp), the costs label_cost.hpp's.
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#include "compose/label_candidates.hpp"
#include "compose/placement_obstacles.hpp"
#include "core/vec.hpp"
#include "frame/frame_model.hpp"
#include "text/text_measure.hpp"

namespace collide::compose {

class LabelProbe {
 public:
  // The frame as placeLabels would place it (its labels not placed yet), for a width_px ×
  // height_px picture.
  LabelProbe(frame::FrameModel frame, int width_px, int height_px, text::TextMeasure& metrics,
             double text_floor_px);
  ~LabelProbe();
  LabelProbe(LabelProbe&&) noexcept;
  LabelProbe& operator=(LabelProbe&&) noexcept;

  // The label of body `body` in panel `panel` (its readout or its mass label) with its candidate
  // places, if it has one.
  const Label* label(std::size_t panel, std::size_t body, bool velocity) const;
  // What the label costs at `box`: its candidate `candidate`'s preference (-1: none, a place
  // between candidates), what it runs into there, and the labels fixed so far.
  double cost(std::size_t panel, const Label& label, const Box& box, int candidate) const;
  // Whether a label at `box` needs a leader line to show whose it is.
  bool needsLeader(std::size_t panel, const Label& label, const Box& box, int candidate) const;
  // The label stands at `box` from now on: the labels asked about next keep clear of it.
  void fix(std::size_t panel, const Label& label, const Box& box, int candidate);

  // The labels fixed so far (and what they left in each panel's scene), to go back to: the
  // planner plans a shot's labels again in another order from the same probes.
  class Fixed {
    friend class LabelProbe;
    std::vector<std::pair<Obstacles, std::vector<std::pair<Box, bool>>>> panels_;
  };
  Fixed fixed() const;
  // Back to `fixed`, what fixed() gave of this probe.
  void restore(const Fixed& fixed);

 private:
  struct Panel;
  frame::FrameModel frame_;
  std::vector<std::unique_ptr<Panel>> panels_;
};

}  // namespace collide::compose
