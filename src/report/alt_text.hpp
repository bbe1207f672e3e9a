#pragma once
// Words that say what a picture or a file shows: the alt text written beside a still, and the
// scene parameters written into file metadata (PNG text chunks, MP4 and WebM tags).
#include <string>
#include <vector>

#include "physics/timeline.hpp"

namespace collide::report {

// A paragraph for a still at simulated time `t_s`: what the scene is, where each body is and how
// it moves, the collisions so far and what the energy bar shows. `title` may be empty.
std::string describeStill(const physics::Timeline& timeline, const std::string& title, double t_s,
                          bool gliders = false);

// One panel of a comparison grid: its heading ("e = 0.5") and its Timeline.
struct PanelDescription {
  std::string heading;
  const physics::Timeline* timeline = nullptr;
  bool gliders = false;  // the bodies are gliders on an air track (drawn with bumpers), not blocks
};

// A still of a comparison grid: what it compares, then every panel described in turn. One
// panel with an empty heading reads as describeStill.
std::string describePanels(const std::vector<PanelDescription>& panels, const std::string& title,
                           double t_s);

// One line with every parameter that shapes the simulation: dimensions, each body's mass, size,
// start position and velocity, e, walls, gravity and duration, e.g.
// "1D; e = 0.5; duration 4 s; cart 1: 1 kg, 0.5 m wide, x = -2 m, v = 2 m/s; ...".
// A record for metadata: English words and English numbers whatever the active language.
std::string describeParameters(const physics::Timeline& timeline);

}  // namespace collide::report
