// SPDX-License-Identifier: MIT
#pragma once
// 2D velocity arrows' forms planned over time (issue 37, docs/architecture.md's layout over
// time). Frame by frame, an arrow takes the first form that has room (arrow_room.hpp): on its
// scale straight on, from its body's edge or beside it, shorter with a break, a below-scale
// mark, or none. As its ball moves and its speed changes, a form may last a frame or two between
// two others: newtons-cradle's ball 5 swinging out to its turn was drawn beside it, from its edge
// for two frames, then as a below-scale mark; billiards-break's ball 9, creeping through the rack,
// had a mark for one frame between frames with none; and the labels planned around the arrow
// jump with each change. So each stretch between two events is sampled at 60 Hz, every body's
// arrow in its own form and in the forms compose may ask for (frame::BodyModel's
// arrow_beside_first: beside first wherever a place there holds it; arrow_hidden: none), and each
// body's forms over the stretch are chosen for the fewest changes, no form between two changes
// lasting fewer than kFewestFrames samples where a choice avoids it, and each sample asked for
// costing a share of a change, so that a form of a few frames is replaced where it stood between
// two others and a form that stands longer is kept (drawn beside for long, an arrow stands still
// while its ball creeps on under it, and labels that keep clear of it jump: billiards-glancing
// 640x360's cue ball broken from 0.167 s to its impact at 0.367 s).
// planned(t) sets it (compose/frame_source_state.hpp), so the labels are planned around the arrow
// as it will be drawn, and a still at t is the video's frame at t.
#include <cstddef>
#include <functional>
#include <mutex>
#include <vector>

#include "frame/frame_model.hpp"
#include "frame/layout.hpp"

namespace collide::compose {

// How frame::bodyArrowShape draws a body's arrow.
enum class ArrowForm {
  kNone,      // no arrow
  kMark,      // a below-scale mark
  kStraight,  // on its scale from the centre, straight on
  kEdge,      // on its scale from the body's edge
  kBreak,     // on its scale, but shortened with a break for want of room straight on
  kBeside,    // whole and to its scale beside the body
};

// A body's arrow's form as drawn with nothing asked for, and with beside first; `crowded`: its
// own form is none for want of room (its speed asks for an arrow). An arrow is hidden only near a
// crowded sample: a ball released from rest shows its velocity from its first move on.
struct ArrowFormChoice {
  ArrowForm own = ArrowForm::kNone;
  ArrowForm beside_first = ArrowForm::kNone;
  bool crowded = false;
};

// Each 2D panel's bodies' arrow forms in `frame` laid out as `layout`, by panel and body (a 1D
// panel: none), with nothing asked for and with beside first.
std::vector<std::vector<ArrowFormChoice>> arrowForms(const frame::FrameModel& frame,
                                                     const frame::FrameLayout& layout);

class ArrowFormPlan {
 public:
  // `sample`: arrowForms of the picture at simulated t_s, nothing asked for;
  // `event_times_s`: every panel's events, in any order.
  using Sample = std::function<std::vector<std::vector<ArrowFormChoice>>(double t_s)>;
  ArrowFormPlan(std::vector<double> event_times_s, double duration_s, Sample sample);

  // Sets BodyModel::arrow_beside_first and arrow_hidden of `frame`'s bodies, the picture at t_s.
  // Safe to call from several threads.
  void apply(frame::FrameModel& frame, double t_s);

  // What a body's arrow is asked for at a sample.
  enum class Ask { kOwn, kBesideFirst, kHidden };
  // The asks, one per sample, that draw `forms` (one body's choices at a stretch's samples)
  // with the fewest changes of form as ArrowFormPlan's comment says.
  static std::vector<Ask> plan(const std::vector<ArrowFormChoice>& forms);

 private:
  // A body's arrow asked for `ask` at the times in (after_s, before_s).
  struct Window {
    std::size_t panel = 0, body = 0;
    Ask ask = Ask::kOwn;
    double after_s = 0.0, before_s = 0.0;
  };
  // The windows of the stretch from starts_s_[stretch] to the next event, planned the first time
  // it is asked for.
  const std::vector<Window>& windowsOf(std::size_t stretch);
  std::vector<Window> windows(std::size_t stretch) const;

  std::vector<double> starts_s_;  // 0, then each event after it, in order
  double duration_s_;
  Sample sample_;
  std::mutex mutex_;
  std::vector<std::vector<Window>> windows_;  // by stretch
  std::vector<bool> planned_;                 // by stretch
};

}  // namespace collide::compose
