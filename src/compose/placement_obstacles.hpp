#pragma once
// What text in a panel keeps clear of, in one place: the label placement (bodies' labels and
// readouts, the crowded scenes' legend) and the dimension placement ask the same Obstacles, and
// each text they place is added to it for the next one to keep its distance from.
//
// In pixels of the picture: bodies (text keeps a gap from them), marks drawn as thick segments
// (arrows, walls, contact flashes, strings, dimension lines, markers, strobe images), regions
// (the track, the ruler, the momentum inset), text placed so far (with a minimum gap: two
// labels that touch read as one) and its leader lines (a leader never strikes through text).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "core/vec.hpp"

namespace collide::compose {

struct Box {
  double x0, y0, x1, y1;
  // Whether the boxes come nearer than pad_x across and pad_y up or down (pads >= 0).
  bool intersects(const Box& o, double pad_x = 0.0, double pad_y = 0.0) const {
    return x0 < o.x1 + pad_x && o.x0 < x1 + pad_x && y0 < o.y1 + pad_y && o.y0 < y1 + pad_y;
  }
  core::Vec2 center() const { return {0.5 * (x0 + x1), 0.5 * (y0 + y1)}; }
};

// A thick segment (a disk when a == b).
struct Capsule {
  core::Vec2 a, b;
  double radius;
};

// Distance from point p to the box (0 inside), to the segment ab, and from the box to the
// segment ab (0 where they meet).
double distance(const Box& box, const core::Vec2& p);
double distance(const core::Vec2& p, const core::Vec2& a, const core::Vec2& b);
double distance(const Box& box, const core::Vec2& a, const core::Vec2& b);
// Closest distance between the segments ab and cd (0 where they cross).
double segmentDistance(const core::Vec2& a, const core::Vec2& b, const core::Vec2& c,
                       const core::Vec2& d);
// Whether the box comes nearer than `limit_px` to the segment ab, or the segments ab and cd
// come nearer than that to each other: the same answers as comparing distance() and
// segmentDistance() with the limit, with the far pairs (most of those placement asks about)
// answered from their bounding boxes alone.
bool nearerThan(const Box& box, const core::Vec2& a, const core::Vec2& b, double limit_px);
bool segmentsNearerThan(const core::Vec2& a, const core::Vec2& b, const core::Vec2& c,
                        const core::Vec2& d, double limit_px);
// The point of the box's outline nearest to p (p itself inside): where a leader line to p
// leaves a text box, as the painter draws it (render/draw/draw_world_labels.cpp).
core::Vec2 nearestOnBox(const Box& box, const core::Vec2& p);

// A body as placement sees it: a disk or an axis-aligned rectangle.
struct BodyOutline {
  bool disk;
  Box bounds;
  // Gap between the box and the body's outline, pixels (0 on or inside it).
  double distanceTo(const Box& box) const;
  // Whether distanceTo(box) < limit_px, the far bodies (most of those placement asks about)
  // answered from the gaps along the axes alone.
  bool nearerThan(const Box& box, double limit_px) const;
  // Whether the segment ab passes through the body.
  bool crossedBy(const core::Vec2& a, const core::Vec2& b) const;
};

// A text reads as the nearest thing's: its own body (or arrow) is nearer it than any other body
// or arrow by at least this many of its lines (a pixel's margin read "m₂" as ball 1's). Labels
// and the numbers beside bodies alike.
inline constexpr double kNearerOwnByLines = 0.25;

// Per body: its arrow (tail to tip, pixels), none at rest or for a rider.
using BodyArrows = std::vector<std::optional<std::pair<core::Vec2, core::Vec2>>>;

// How many other bodies a text at `box` could be read as naming: those whose outline or arrow
// comes within `nearer_by_px` of `own_px`, the text's distance from what it names (body `owner`,
// or its arrow, as the caller measures it). 0: clearly nearer its own than anything else, by at
// least `nearer_by_px` (a tie counts as clear). A body riding on `owner` (moves_with[i] == owner:
// a bullet in its block) is part of it. Label placement counts it against each candidate (each
// body read as the owner costs an overlap), the numbers beside bodies and arrows place only where
// it is 0.
int readAsOthers(const Box& box, double own_px, std::size_t owner,
                 const std::vector<BodyOutline>& bodies, const std::vector<int>& moves_with,
                 const BodyArrows& arrows, double nearer_by_px);

class Obstacles {
 public:
  // Text stays inside `clip`, keeps `body_gap` from bodies, and keeps text_gap_x across and
  // text_gap_y up or down from other text.
  Obstacles(const Box& clip, double body_gap, double text_gap_x, double text_gap_y);

  void addBody(const BodyOutline& body) {
    bodies_.push_back(body);
    changed();
  }
  // A mark drawn as a thick segment; `owner`: the body it belongs to (its arrow), or -1.
  void addMark(const Capsule& mark, int owner = -1) {
    marks_.push_back({mark, owner});
    changed();
  }
  void addRegion(const Box& region) {
    regions_.push_back(region);
    changed();
  }
  void addText(const Box& text) {
    texts_.push_back(text);
    changed();
  }
  void addLeader(const core::Vec2& a, const core::Vec2& b) {
    leaders_.push_back({a, b});
    changed();
  }
  // Changes with every addition, to a number no other state of any Obstacles has had (a copy
  // keeps it, holding the same): what was found against these obstacles holds while it stays.
  std::uint64_t revision() const { return revision_; }

  // What a text box at `box` would run into: leaving the clip, a region, a mark, a body nearer
  // than the body gap, text nearer than the text gaps, a leader through it. 0: free.
  int hits(const Box& box) const;
  bool isFree(const Box& box) const { return hits(box) == 0; }
  // Whether two text boxes keep the text gaps.
  bool textsApart(const Box& a, const Box& b) const;
  // What a leader line from a to b (the body or arrow it names, `owner`'s) would strike through:
  // text, a mark (but `owner`'s arrow, where a readout's leader ends), a body other than
  // `owner`. 0: clear.
  int leaderHits(const core::Vec2& a, const core::Vec2& b, int owner, bool to_arrow) const;

  const Box& clip() const { return clip_; }
  const std::vector<BodyOutline>& bodies() const { return bodies_; }
  const std::vector<Box>& regions() const { return regions_; }
  double bodyGap() const { return body_gap_; }

 private:
  struct Mark {
    Capsule shape;
    int owner;
  };
  struct Segment {
    core::Vec2 a, b;
  };
  void changed();

  Box clip_;
  double body_gap_, text_gap_x_, text_gap_y_;
  std::uint64_t revision_ = 0;
  std::vector<BodyOutline> bodies_;
  std::vector<Mark> marks_;
  std::vector<Box> regions_;
  std::vector<Box> texts_;
  std::vector<Segment> leaders_;
};

}  // namespace collide::compose
