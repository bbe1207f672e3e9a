// SPDX-License-Identifier: MIT
#pragma once
// 2D velocity arrows' forms planned over time (issue 37, docs/architecture.md's layout over
// time). Frame by frame, an arrow on its scale that loses its room straight on (a ball nearing
// the rack or a cushion) is first drawn shorter with a break, and beside its ball only where the
// break has no room either: two changes of form in a few frames (billiards-break's cue ball with
// a break for one frame at 0.117 s, newtons-cradle's ball 1 for two at 0.267-0.283 s), and the
// labels planned around the arrow jump with each. Drawing it beside its ball before a break in
// every frame cost more label jumps than it saved (42ba176, reverted): a beside arrow is longer,
// and where its ball creeps on it changed form back and forth. So the picture is sampled once per
// stretch between two events (at 60 Hz), and only where a break of a few frames is followed by
// the arrow beside its ball in the same stretch does the body's arrow go beside it first
// (frame::BodyModel::arrow_beside_first) from the frame after its last sample straight on to the
// stretch's end: one change of form where there were two. A break that stands longer reads, and
// is kept.
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
  kNone,      // no arrow, or one below its scale
  kStraight,  // from the centre or the edge, straight on
  kBreak,     // on its scale, but shortened with a break for want of room straight on
  kBeside,    // whole and to its scale beside the body
};

// Each 2D panel's bodies' arrow forms in `frame` laid out as `layout`, by panel and body (a 1D
// panel: none).
std::vector<std::vector<ArrowForm>> arrowForms(const frame::FrameModel& frame,
                                               const frame::FrameLayout& layout);

class ArrowFormPlan {
 public:
  // `sample`: arrowForms of the picture at simulated t_s, no arrow planned beside first;
  // `event_times_s`: every panel's events, in any order.
  using Sample = std::function<std::vector<std::vector<ArrowForm>>(double t_s)>;
  ArrowFormPlan(std::vector<double> event_times_s, double duration_s, Sample sample);

  // Sets BodyModel::arrow_beside_first of `frame`'s bodies, the picture at t_s. Safe to call
  // from several threads.
  void apply(frame::FrameModel& frame, double t_s);

 private:
  // A body whose arrow goes beside first after after_s (exclusive) to its stretch's end.
  struct Window {
    std::size_t panel = 0, body = 0;
    double after_s = 0.0;
  };
  // The windows of the stretch from starts_s_[stretch] to the next event, planned the first time
  // it is asked for.
  const std::vector<Window>& windowsOf(std::size_t stretch);
  std::vector<Window> plan(std::size_t stretch) const;

  std::vector<double> starts_s_;  // 0, then each event after it, in order
  double duration_s_;
  Sample sample_;
  std::mutex mutex_;
  std::vector<std::vector<Window>> windows_;  // by stretch
  std::vector<bool> planned_;                 // by stretch
};

}  // namespace collide::compose
