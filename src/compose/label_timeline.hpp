// SPDX-License-Identifier: MIT
#pragma once
// Layout planned over time (docs/architecture.md): where a picture's labels stand is decided
// over the timeline, not frame by frame. Each shot (the time from one event to the next) is walked
// at a fixed step, each label staying where it stood, carried along by its body (its side of its
// body: label_placement.hpp's LabelSlot), unless something runs into it there: in a shot a label
// holds its place firmly (kHeldLines in label_timeline.cpp). A shot is walked twice: once from
// places chosen a little after its event (each label on its side of before where that is free),
// then again from the places the labels took at its end, so that bodies closing in, whose labels
// have least room at the end, have them there from the start. A frame at any time takes the
// places of the step it falls in, so a still at t is the video's frame at t whatever the frame
// rate or the order frames are asked for. Where a label changes its place it glides there from
// where it stood over at least kGlide_s, as long as the way is free; where it is not, it takes
// its new place at once.
#include <cstddef>
#include <functional>
#include <mutex>
#include <vector>

#include "compose/label_placement.hpp"
#include "core/vec.hpp"
#include "frame/frame_model.hpp"

namespace collide::compose {

// Events nearer than this to a shot's start belong to that shot: a burst of impacts (a break) is
// one shot.
inline constexpr double kShortestShot_s = 0.3;
// A change of place glides over at least this long (simulated time), and slowly enough that a
// label moves no faster than kGlidePxPerS beyond its body (under 2 px a frame at 60 fps), or
// kEventGlidePxPerS in the kShortestShot_s after an event (under 8 px a frame).
inline constexpr double kGlide_s = 0.3;
inline constexpr double kGlidePxPerS = 100.0;
inline constexpr double kEventGlidePxPerS = 400.0;

// The shots' starts, simulated seconds: 0, the first event, then each event at least
// kShortestShot_s after the last start (`event_times_s` in any order).
std::vector<double> shotStarts(std::vector<double> event_times_s);
// The shot t_s falls in: the index of the last start at or before it.
std::size_t shotOf(const std::vector<double>& shot_starts_s, double t_s);

class LabelTimeline {
 public:
  // What the timeline needs of the picture: its frame at t with no label placed, its placement
  // (placeLabels with a plan to keep and the places chosen) and its bodies' pixel centres (per
  // panel, as the painters place them).
  struct Picture {
    std::function<frame::FrameModel(double t_s)> compose;
    std::function<void(frame::FrameModel&, const LabelSlots* keep, LabelSlots* chosen)> place;
    std::function<std::vector<std::vector<core::Vec2>>(const frame::FrameModel&)> body_px;
  };

  // `event_times_s`: every panel's events, simulated seconds, in any order.
  LabelTimeline(std::vector<double> event_times_s, double duration_s, Picture picture);

  // Places the labels of `frame`, the picture at t_s (simulated) composed by picture.compose.
  // Safe to call from several threads.
  void place(frame::FrameModel& frame, double t_s);

 private:
  // A label placed by its body at one step: where placement put it (`placed_px`, its box's top
  // left corner), where it is shown (gliding from an earlier place), its body's pixel centre.
  struct LabelAt {
    std::size_t panel = 0, body = 0;
    bool velocity = false;
    core::Vec2 placed_px{0.0, 0.0}, body_px{0.0, 0.0};
    core::Vec2 shown_px{0.0, 0.0};
    // Its glide: from this far off its body's centre, from start_s for length_s; length 0: none.
    core::Vec2 glide_from_offset_px{0.0, 0.0};
    double glide_start_s = 0.0, glide_length_s = 0.0;
  };
  struct Step {
    double t_s = 0.0;
    LabelSlots slots;
    std::vector<LabelAt> placed;
  };

  std::size_t shotAt(double t_s) const;
  // The labels `frame` places by their bodies (placed_px and body_px only).
  std::vector<LabelAt> placedLabels(const frame::FrameModel& frame);
  // The steps of `shot`, walked (with every shot before it) the first time it is asked for.
  const std::vector<Step>& walkOf(std::size_t shot);
  std::vector<Step> walk(std::size_t shot, const Step* before);
  // The places chosen at t_s, keeping `keep` (null: none) where free.
  LabelSlots planAt(double t_s, const LabelSlots* keep);
  // The steps from start_s to end_s, from `plan`, after `before` (the shot before's last step).
  std::vector<Step> walkFrom(double start_s, double end_s, const LabelSlots& plan,
                             const Step* before);
  // The step at t_s: after `last` in its shot, or (last null) the shot's first, from `plan`,
  // after `shot_before` (the last step of the shot before; null: none).
  Step step(double t_s, const Step* last, const LabelSlots& plan, const Step* shot_before);
  static LabelSlots wanting(LabelSlots slots, const std::vector<LabelAt>& labels,
                            const std::function<core::Vec2(const LabelAt&)>& shown);
  // Starts, continues or ends `label`'s glide, placed at t_s, given where it was at the step
  // before (`before`), and sets where it is shown.
  static void glideOn(LabelAt& label, const LabelAt& before, double t_s, double px_per_s);
  // Where a label gliding as `glide` says is shown at t_s, its body at body_px and placement
  // putting it at placed_px.
  static core::Vec2 shownAt(const LabelAt& glide, const core::Vec2& placed_px,
                            const core::Vec2& body_px, double t_s);
  // Where a label planned as `planned` stands at t_s, its body at body_px.
  static core::Vec2 plannedAt(const LabelAt& planned, const core::Vec2& body_px, double t_s);

  std::vector<double> shot_starts_s_;
  double duration_s_;
  Picture picture_;
  std::mutex mutex_;
  std::vector<std::vector<Step>> walks_;  // the shots walked so far, from the first
};

}  // namespace collide::compose
