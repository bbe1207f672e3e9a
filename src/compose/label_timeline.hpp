// SPDX-License-Identifier: MIT
#pragma once
// Layout planned over time (docs/architecture.md): where a picture's labels stand is decided
// over the timeline, not frame by frame. Each shot (the time from one event to the next) is walked
// at a fixed step, each label staying where it stood, carried along by its body (its side of its
// body: label_placement.hpp's LabelSlot), unless something runs into it there: in a shot a label
// holds its place firmly (kHeldLines in label_timeline.cpp). A shot is walked twice: once from
// places chosen a little after its event (each label on its side of before where that is free),
// then again from the places the labels took at its end, so that bodies closing in, whose labels
// have least room at the end, have them there from the start. Then each label's way is planned
// over the whole shot: where it must change its place by its body at a step, it sets off early
// enough to get there at that step moving no faster than kGlidePxPerS beyond its body (under 2 px
// a frame at 60 fps), or kEventGlidePxPerS in the kShortestShot_s after an event (under 8 px a
// frame), so it never jumps; it leaves the place of the shot before the same way, unless that
// place runs into something in the new shot: then it starts elsewhere, one jump at the event. In
// a 2D panel, where no glide gets it out of the way in time (a ball in flight crosses the
// picture faster than a label glides around it), it jumps once, at a step, rather than run into
// something there (the frame would place it elsewhere: a jump there and another back). A
// frame at any time stands between the places of the two steps around it, so a still at t is the
// video's frame at t whatever the frame rate or the order frames are asked for.
#include <cstddef>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include "compose/label_fades.hpp"
#include "compose/label_placement.hpp"
#include "compose/label_probe.hpp"
#include "compose/placement_obstacles.hpp"
#include "core/vec.hpp"
#include "frame/frame_model.hpp"

namespace collide::compose {

// Events nearer than this to a shot's start belong to that shot: a burst of impacts (a break) is
// one shot.
inline constexpr double kShortestShot_s = 0.3;
// The step a shot is walked at (simulated time): a frame takes the places of the step it falls in.
inline constexpr double kStep_s = 1.0 / 30.0;
// A frame this near a step's instant falls at it (frame k / fps and the step's time differ in
// their last bits).
inline constexpr double kStepRounding_s = 1e-9;
// The fastest a label moves beyond its body across and up or down, pixels per simulated second
// (a video plays at most as fast as simulated time): under 2 px a frame at 60 fps with a pixel
// left for the rounding of a text's baseline, and under 8 px in the kShortestShot_s after an
// event.
inline constexpr double kGlidePxPerS = 60.0;
inline constexpr double kEventGlidePxPerS = 360.0;
// A way that moves a label farther than this beyond its body from one step to the next jumps
// there at once: spread over the frames between (two at 60 fps) it would jump in each of them,
// more than 2 px a frame, or 8 px in the kShortestShot_s after an event.
inline constexpr double kJumpPx = 4.0;
inline constexpr double kEventJumpPx = 16.0;

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
    // What label places cost in the frame (composed, its labels not placed yet).
    std::function<LabelProbe(const frame::FrameModel&)> probe;
    // The playback time at which simulated time t is shown (slow motion stretches a stay; the
    // identity where empty).
    std::function<double(double t_s)> playback_at;
  };

  // `event_times_s`: every panel's events, simulated seconds, in any order.
  LabelTimeline(std::vector<double> event_times_s, double duration_s, Picture picture);

  // Places the labels of `frame`, the picture at t_s (simulated) composed by picture.compose.
  // A label changing places between its body and its legend fades out at the one and then in at
  // the other (label_fades.hpp). Safe to call from several threads.
  void place(frame::FrameModel& frame, double t_s);
  // Places them where the video's frame at t_s does, every text whole (a still: a fade is
  // motion), without asking where each fades.
  void placeWhole(frame::FrameModel& frame, double t_s) { placeOnWays(frame, t_s); }

 private:
  // A label placed by its body at one step: where placement put it (`placed_px`, its box's top
  // left corner), its body's pixel centre, and where it is shown (on its way to a place it takes
  // later, or from the one it had); `rides`: from the step before to this one it moves with its
  // body (else it stands, as a label held by the frame's edge while its body moves on).
  struct LabelAt {
    std::size_t panel = 0, body = 0;
    bool velocity = false;
    core::Vec2 placed_px{0.0, 0.0}, body_px{0.0, 0.0};
    core::Vec2 shown_px{0.0, 0.0};
    core::Vec2 size_px{0.0, 0.0};  // its text's: as placed, then as its way plans it
    bool rides = true;
    bool free = true;  // its way's place at this step runs into nothing (as the shot's probe saw)
    // Placement takes its way's place at this step: it runs into nothing and continues no other
    // label's line (two that read as one line are placed again, one of them in the legend).
    bool taken = true;
    bool two_d = false;  // in a 2D panel
    // How far it moved since `was` (the same label a step before): moveBetween's measure, beyond
    // its body or standing still, whichever is nearer (label_way_moves.hpp).
    double movedFrom(const LabelAt& was) const;
    // The box it is shown in (shown_px, size_px).
    Box shownBox() const {
      return {shown_px.x(), shown_px.y(), shown_px.x() + size_px.x(), shown_px.y() + size_px.y()};
    }
  };
  struct Step {
    double t_s = 0.0;
    LabelSlots slots;
    std::vector<LabelAt> placed;
    std::vector<int> arrow_rows;  // each panel's bodies' (frame::BodyModel::arrow_row)
    bool halfway = false;         // a step halfway between two, where arrows change rows
    bool two_d = false;           // the picture has a 2D panel
    // The slots of labels listed in a legend when last shown and not shown at this step (a
    // readout whose body stands still): where one comes back it is listed where it stood.
    LabelSlots gone;
    // Its slots and those gone: what the step after it keeps.
    LabelSlots remembered() const;
  };
  // The picture just after a shot's end (the next shot's first step): what the labels' places
  // cost there, and its bodies' pixel centres, so that a shot ends where its labels can stay on
  // across the event.
  struct AfterEnd {
    LabelProbe probe;
    std::vector<std::vector<core::Vec2>> body_px;
    std::vector<AfterEnd> later;  // the next shot's first step after its event, where it has one
  };

  std::size_t shotAt(double t_s) const;
  // The picture at t_s with no label placed (picture_.compose), composed once for the shot being
  // walked: its steps are composed for each walk, for the probes and for the walk that lists
  // jumping labels. Only under mutex_ (walkOf).
  frame::FrameModel composedAt(double t_s) const;
  // The labels of `frame` placed on their ways at t_s, before any fade.
  // Returns the labels it could not place on their ways and placed farther off than a jump (a
  // frame between two steps off the plan): a frame shows them nowhere rather than there.
  LabelSlots placeOnWays(frame::FrameModel& frame, double t_s);
  // What placesOf finds the places of: a body's mass or velocity label, or its arrow's number.
  enum class Placed { kMass, kVelocity, kArrowTag };
  // Where the label (or arrow number) `what` of `key` stands at each step of the shots first to
  // last (label_fades.hpp), found once: every frame of those shots asks for it.
  std::shared_ptr<const std::vector<PlaceAtStep>> placesOf(const LabelSlot& key, Placed what,
                                                           std::size_t first, std::size_t last);
  std::vector<PlaceAtStep> findPlaces(const LabelSlot& key, std::size_t first, std::size_t last);
  // A label as the frame at a step shows it (placeOnWays at the step's instant): by its body
  // (its box) or in its legend (its line's top left corner).
  struct ShownLabel {
    std::size_t panel = 0, body = 0;
    bool velocity = false;
    LabelPlace at = LabelPlace::kNowhere;
    Box box;
  };
  // A body's number at its lifted arrow's tail as the frame at a step shows it
  // (BodyModel::arrow_tag_at), and its body's pixel centre there.
  struct ShownTag {
    std::size_t panel = 0, body = 0;
    Box box;
    core::Vec2 body_px{0.0, 0.0};
  };
  struct ShownStep {
    std::vector<ShownLabel> labels;
    std::vector<ShownTag> arrow_tags;
  };
  using ShownSteps = std::vector<ShownStep>;
  // What the frame at each step of `shot` shows, found once for every label's places.
  std::shared_ptr<const ShownSteps> shownOf(std::size_t shot);
  // Where the number at the arrow of body `key` (panel, body) stands at each step of the shots
  // first to last, as the frames at the steps place it (placeArrowTags chooses its place frame
  // by frame): a new place where it moves farther than a jump beyond its body, so that it fades
  // from one place to the other as a label does (label_fades.hpp).
  std::vector<PlaceAtStep> findArrowTagPlaces(const LabelSlot& key, std::size_t first,
                                              std::size_t last);
  // Fades each number at a lifted arrow of `frame` by its places over the shots first to last.
  void fadeArrowTags(frame::FrameModel& frame, std::size_t first, std::size_t last, double t_s,
                     double playback_s);
  // Whether the frame at `steps[k]` shows the label of `key` elsewhere than the plan has it
  // (at `planned`): the frame's place, else nothing.
  std::optional<LabelPlace> offPlan(const std::vector<Step>& steps, std::size_t k,
                                    const std::vector<ShownLabel>& shown, const LabelSlot& key,
                                    LabelPlace planned) const;
  // The labels `frame` places by their bodies (placed_px and body_px only).
  std::vector<LabelAt> placedLabels(const frame::FrameModel& frame);
  // The steps of `shot`, walked (with every shot before it) the first time it is asked for.
  const std::vector<Step>& walkOf(std::size_t shot);
  std::vector<Step> walk(std::size_t shot, const Step* before);
  // The places chosen at t_s, keeping `keep` (null: none) where free, and the slots of `keep`
  // listed in a legend whose labels are not shown at t_s (Step::gone).
  LabelSlots planAt(double t_s, const LabelSlots* keep);
  // The steps from start_s to end_s, from `plan`; the last a hair before end_s where the shot
  // `ends_at_event`, else at end_s (the video's end). `listing` (null: none): labels listed in
  // their legends at every step, where the legend has room.
  std::vector<Step> walkFrom(double start_s, double end_s, const LabelSlots& plan,
                             bool ends_at_event, const LabelSlots* listing = nullptr);
  // Adds the step at t_s after the last of `steps` (and one halfway where arrows change rows).
  void addStep(std::vector<Step>& steps, double t_s, const LabelSlots& plan,
               const LabelSlots* listing);
  // The step at t_s: after `last` in its shot, or (last null) the shot's first, from `plan`.
  Step step(double t_s, const Step* last, const LabelSlots& plan, const LabelSlots* listing);
  // The labels of a 2D panel whose ways through `steps` still jump (move farther than a glide
  // beyond their bodies from one step to the next), and how many such jumps the steps hold.
  std::pair<LabelSlots, std::size_t> jumpingWays(const std::vector<Step>& steps) const;
  // Where a 2D label's way through the shot from start_s to end_s still jumps, the shot walked
  // again from `plan` with that label listed in its legend throughout, kept where its ways jump
  // fewer times. `after_unfixed`: after's probe as it was before the shot's ways were planned.
  void listJumping(std::vector<Step>& steps, double start_s, double end_s, bool ends_at_event,
                   const LabelSlots& plan, const Step* before, AfterEnd* after,
                   const std::optional<LabelProbe::Fixed>& after_unfixed);
  static LabelSlots wanting(LabelSlots slots, const std::vector<LabelAt>& labels,
                            const std::function<core::Vec2(const LabelAt&)>& shown);
  // Plans each label's way through a shot's `steps`, after `before` (the shot before's last
  // step; null: none): shown_px moving no faster than the glide speeds beyond its body or
  // standing, as near its place as
  // that allows, arriving at each place it must take in time.
  // `after`: the picture after the shot's end (null: the video's last shot).
  void planWays(std::vector<Step>& steps, const Step* before, AfterEnd* after) const;
  // A label listed in its legend at a step and placed by its body at the next stays listed there
  // where its way's place is not taken (it runs into something or continues another label's
  // line, as the shot's probes saw it): placed anyway, the frames of that step refused it and
  // placed it elsewhere, pushing the others aside there and back (air-drag-throw's m₂ leaving
  // the legend at 0.2 s in one line with m₁: m₁ moved 78 px and back). It leaves the legend at
  // the first step whose place is taken, not a jump: the legend's line goes as it appears.
  static void keepListedUntilTaken(std::vector<Step>& steps);
  // What label places cost at each of `steps`, each label's text as wide as its widest there.
  std::vector<LabelProbe> probesOf(const std::vector<Step>& steps) const;
  // The scene just after the event at end_s, and at later_s (< 0: none), the next shot's first
  // step after it.
  AfterEnd afterEnd(double end_s, double later_s) const;
  // The way of the label `key` through the shot (label_ways.hpp), against each step's scene
  // (`probes`, where the labels planned before it stand), fixed in the probes for the next.
  void planWay(std::vector<Step>& steps, const Step* before, std::vector<LabelProbe>& probes,
               AfterEnd* after, const LabelAt& key) const;
  // Its way through steps first to last, where its candidates are of one kind, from where it
  // stood at the step before (`was`, carried along by its body; null: from where it is best).
  void planRun(std::vector<Step>& steps, std::size_t first, std::size_t last, const LabelAt* was,
               std::vector<LabelProbe>& probes, AfterEnd* after, const LabelAt& key) const;
  // The places the labels' ways give them `share` of the way from `step` to `next` (null: none),
  // their bodies at body_px, to keep firmly; a way in a 2D panel that moves farther than jump_px
  // beyond its body between the two steps jumps halfway. `keep_right_edges`: each 2D label's
  // slot carries its planned width (LabelSlot::planned_width_px).
  static LabelSlots plannedAt(const Step& step, const Step* next, double share,
                              const std::vector<std::vector<core::Vec2>>& body_px, double jump_px,
                              bool keep_right_edges);
  // Adds to `keep` the labels `next` places that `keep` has no slot for, where `next` has them
  // (carried along by their bodies, at body_px).
  static void appendComing(LabelSlots& keep, const Step& next,
                           const std::vector<std::vector<core::Vec2>>& body_px);
  // Makes the labels of `keep` that `frame` placed where they want hold there, and the others
  // (refused their places) free to look for another.
  void holdOnTheirWays(const frame::FrameModel& frame, LabelSlots& keep);
  // Whether every label `keep` lists (LabelSlot::holds) is stated in `frame`: in its legend or,
  // where the legend had no room for it, by its body. Else it is placed again, free to leave.
  bool statesListed(const frame::FrameModel& frame, const LabelSlots& keep);
  // The labels of `keep` wanted by their bodies that `frame` places farther than jump_px from
  // where they are wanted, or not by their bodies.
  LabelSlots farOffTheirWays(const frame::FrameModel& frame, const LabelSlots& keep,
                             double jump_px);
  // Whether every label `keep` wants somewhere is placed by its body in `frame`.
  bool allPlaced(const frame::FrameModel& frame, const LabelSlots& keep);
  // Whether every label placed in `frame` stands where `keep` wants it.
  bool onTheirWays(const frame::FrameModel& frame, const LabelSlots& keep);
  // The fastest a label (in a 2D panel or not) may move beyond its body at t_s, pixels per
  // simulated second.
  double glideSpeedAt(double t_s, bool two_d) const;
  // The farthest a label (in a 2D panel or not) may move beyond its body from one step to the
  // next at t_s without jumping: kEventJumpPx where it may glide fast, else kJumpPx.
  double jumpPxAt(double t_s, bool two_d) const {
    return glideSpeedAt(t_s, two_d) > kGlidePxPerS ? kEventJumpPx : kJumpPx;
  }

  std::vector<double> shot_starts_s_;
  double duration_s_;
  Picture picture_;
  std::mutex mutex_;
  // The shots walked so far, from the first (a deque: a shot's steps stay where they are while
  // later shots are walked on another thread).
  std::deque<std::vector<Step>> walks_;
  // The frames composedAt kept, by their instant: the shot's being walked and those just after
  // its end (the next shot's first).
  mutable std::map<double, frame::FrameModel> composed_;
  // placesOf's answers by label (panel, body, what) and shots (first, last), and how many
  // steps they hold: all let go where that passes kMostPlacesKept (label_timeline_fades.cpp).
  using PlacesKey = std::tuple<std::size_t, std::size_t, Placed, std::size_t, std::size_t>;
  std::mutex places_mutex_;
  std::map<PlacesKey, std::shared_ptr<const std::vector<PlaceAtStep>>> places_;
  std::size_t places_kept_ = 0;
  // shownOf's answers by shot, and how many steps they hold: all let go where that passes
  // kMostShownKept (label_timeline_fades.cpp).
  std::mutex shown_mutex_;
  std::map<std::size_t, std::shared_ptr<const ShownSteps>> shown_;
  std::size_t shown_kept_ = 0;
};

// The label of `key` in `placed` (const or not), if placed: for label_timeline*.cpp.
template <typename Labels, typename LabelAt>
auto findLabel(Labels& placed, const LabelAt& key) -> decltype(&placed.front()) {
  for (auto& label : placed) {
    if (label.panel == key.panel && label.body == key.body && label.velocity == key.velocity) {
      return &label;
    }
  }
  return nullptr;
}

// The slot of `key` at `steps[k]` where it is listed in its legend there (by no body), if so:
// for label_timeline*.cpp.
template <typename Steps, typename LabelAt>
std::optional<LabelSlot> listedAt(const Steps& steps, std::size_t k, const LabelAt& key) {
  const LabelSlot* slot = findLabel(steps[k].slots, key);
  if (slot == nullptr || slot->candidate >= 0 || !slot->legend) return std::nullopt;
  if (findLabel(steps[k].placed, key) != nullptr) return std::nullopt;
  return *slot;
}

}  // namespace collide::compose
