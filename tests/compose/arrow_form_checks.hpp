// SPDX-License-Identifier: MIT
#pragma once
// Velocity arrows' forms read frame by frame (issue 37): an arrow that is drawn on its scale from
// its body's centre, then with a break, then beside its body, each for a frame or two, flickers.
// VideoFramesTest's rule "arrow form flickers".
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "frame/drawn_items.hpp"
#include "frame/frame_model.hpp"

namespace collide::test {

// A form shown for fewer frames than this between two changes of form, at 60 fps, flickers.
inline constexpr int kFewestFormFrames = 3;

// A body's velocity arrow as a frame draws it, and its body's speed there.
struct ArrowFormAt {
  // "none", "below scale", "off scale" (a break), or on its scale "from the centre", "from the
  // edge" (its tail ahead of the centre) or "beside" its body (its line off the centre); a 1D
  // arrow on its scale is "on scale" (drawn back from a wall it runs along the same line).
  std::string form;
  double speed_mps = 0.0;
};
using ArrowFormsAt = std::map<std::pair<int, int>, ArrowFormAt>;  // by (panel, body)

// Every body's arrow form in a frame: `model` the frame, `items` as it is drawn.
ArrowFormsAt arrowFormsAt(const frame::FrameModel& model,
                          const std::vector<frame::DrawnItem>& items);

// Watches a video's arrows frame by frame: a form that lasts fewer than kFewestFormFrames frames
// between two changes of form, all with no event between them, flickers, unless its body's speed
// makes both changes: the form says a shorter arrow (none, a below-scale mark, on its scale, off
// it) than the one before where its speed is lower, a longer one where higher, and so against
// the one after (a velocity that passes through zero or the scale's threshold).
class ArrowFormWatch {
 public:
  // The next frame at simulated t_s; `after_event`: an event falls between it and the one before.
  void add(double t_s, const ArrowFormsAt& forms, bool after_event);
  // The flickers found, described, once the last frame is added.
  std::vector<std::string> finish();

 private:
  struct Seen {
    double t_s;
    ArrowFormAt at;
  };
  void endStretch();
  std::map<std::pair<int, int>, std::vector<Seen>> stretch_;  // the frames since the last event
  std::vector<std::string> found_;
};

}  // namespace collide::test
