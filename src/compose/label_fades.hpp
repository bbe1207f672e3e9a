// SPDX-License-Identifier: MIT
#pragma once
// A label that changes places between its body and its panel's legend (the bodies close in and
// leave it no room, or open up again) fades rather than jumps: within a shot it fades out over
// kFade_s where it stood and then in over kFade_s where it goes (its body's number with its
// legend's lines), so that in a video nothing leaps across the picture; at an event it fades out
// before the event and stands at its new place from the event on, as the readouts change there
// (so a still just after an impact shows every label whole). A label whose way by its body jumps
// (no glide gets it to its next place in time) fades the same way from the one place to the
// other, where it stands long enough at each (label_timeline_fades.cpp). Each text is only ever
// drawn where the layout over time placed it (label_timeline.hpp), so a fading text runs into
// nothing the layout kept it clear of; the steps of that layout say when each label changes
// places.
#include <cstddef>
#include <vector>

#include "frame/frame_model.hpp"

namespace collide::compose {

// How long a fade takes, playback seconds: at least the 0.3 s a change of place eases over, with
// a hair to spare for a frame's rounding.
inline constexpr double kFade_s = 0.32;
// A label fades out this long (playback) before the last step it stands at its old place (a
// frame at 60 fps), so that no frame shows it at one place and the next at the other.
inline constexpr double kFadeGap_s = 1.0 / 60.0;

// Where a label is shown at a step of the layout over time.
enum class LabelPlace { kNowhere, kBody, kLegend };
struct PlaceAtStep {
  double t_s = 0.0;
  LabelPlace at = LabelPlace::kNowhere;
  bool shot_start = false;  // the first step of a shot (at its event)
  // Which of its places by its body: a new one where its way jumps (moves farther beyond its
  // body from the step before than a glide may), so that it fades out at the one and in at the
  // other like a label changing places between its body and its legend.
  int place = 0;
  // Not shown: a stay too short to be read between jumps (hideShortStays).
  bool hidden = false;
  // The frame at this step could not place it where the plan has it and shows it elsewhere
  // (`at`, a place of its own): like a jump there and back, hidden where it is short.
  bool off_plan = false;
  // When the step is shown in a video (slow motion stretches a stay), playback seconds.
  double playback_s = 0.0;
};

// A label that jumps within a shot between two places by its body, or two of its legend, is not
// shown where it stands shorter than kShortestStay_s of playback (a stay in slow motion lasts
// longer): faded in and out there it would hardly be seen whole, and shown whole it would leap
// (a label hopping round a ball in flight). It fades out at the place before such a stay and in
// at the first place after it where it stays long enough. A stay at the video's start or end
// needs one fade fewer.
inline constexpr double kShortestStay_s = 1.0;

// Marks hidden each run of `places` (steps of one label, in order; `from_start`: the first is
// the video's first step, `to_end`: the last is its last) at one place that it jumps to or from
// another of the same kind (both by its body, or both in its legend) at the next step within a
// shot, where it stands too short (kShortestStay_s) to be read. At an event a move to another
// place is no jump: it fades out before the event and stands whole from it, however short. A
// stay the frames take off the plan (PlaceAtStep::off_plan) is hidden where it is too short,
// and the planned stays beside it fade there however short they are. A stay is measured within
// its shot, so that every frame that sees it judges it alike.
void hideShortStays(std::vector<PlaceAtStep>& places, bool from_start, bool to_end);

// The opacity of a label shown at `shown` (its body or its legend) at t_s, from its places at
// the steps around t_s (`steps`, in order; `from_start`: the first is the video's first). In a
// run of steps at one place that it leaves for the other place it fades out before the run's
// last step; in one it reaches from the other place within a shot it fades in after the run's
// first step, and between two steps it stands at neither (a frame there may take either's
// places) it is not seen. A run that would come or go half seen (it starts whole, where it was
// shown nowhere, at the video's start or at an event, too short to fade out whole; or it fades
// in and vanishes too soon after) is not seen at all, nor is one shown nowhere before and after
// it for less than kFade_s (a blink). Elsewhere 1. Fades and stays are timed in playback
// seconds (`playback_s`: when t_s is shown; PlaceAtStep::playback_s), as a video shows them.
double placeOpacity(const std::vector<PlaceAtStep>& steps, bool from_start, LabelPlace shown,
                    double t_s, double playback_s);

// Fades the label (panel, body, velocity) of `frame` to `opacity` where it is shown: by its
// body, or its lines in its panel's legend.
void fadeLabel(frame::FrameModel& frame, std::size_t panel, std::size_t body, bool velocity,
               float opacity);

// Each body's number (inside it or beside it) as solid as the most solid of its lines in its
// panel's legend, where it has any: the number that names them comes and goes with them. (The
// number at a lifted arrow's tail comes and goes with the lift, and fades from one place by the
// arrow to another like a label: LabelTimeline::fadeArrowTags.)
void fadeNumbers(frame::FrameModel& frame);

// Every text of `frame` solid (a still: a fade is motion).
void showWhole(frame::FrameModel& frame);

}  // namespace collide::compose
