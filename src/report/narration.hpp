#pragma once
// What happens in a simulation, told in plain words with numbers, as timed cues: one at the start,
// one per collision (at the collision's exact time) and one at the end. Captions (WebVTT, SRT,
// an MP4 subtitle stream) are written from these cues.
#include <string>
#include <vector>

#include "physics/timeline.hpp"

namespace collide::report {

struct Cue {
  double start_s = 0.0;  // shown from this simulated (= video) time
  double end_s = 0.0;    // until this time, > start_s
  std::string text;      // one or more lines separated by '\n'; never an empty line
};

struct NarrationOptions {
  std::string title;                   // the scene's title, opens the first cue; may be empty
  double end_s = 0.0;                  // length of the video, s; 0 means the timeline's duration
  int max_collision_cues = 50;         // later collisions are summed up in one cue
  double min_collision_shown_s = 2.0;  // the end cue waits this long after the last collision cue
  double end_cue_s = 2.0;              // the end cue is shown for (at most) this long
};

// Collisions less than this apart share one cue (e.g. Newton's cradle, three bodies at once), s.
inline constexpr double kSameInstantS = 1e-3;

// Cues in time order; they never overlap, each ends where the next begins, the last at end_s.
// Collision cues start exactly at the (first) collision's time.
std::vector<Cue> narrate(const physics::Timeline& timeline, const NarrationOptions& options);

}  // namespace collide::report
