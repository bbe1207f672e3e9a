// SPDX-License-Identifier: MIT
// LabelTimeline's fades: a label changing places between its body and its legend fades out at
// the one and then in at the other (label_fades.hpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

#include "compose/label_cost.hpp"
#include "compose/label_fades.hpp"
#include "compose/label_timeline.hpp"
#include "compose/label_way_moves.hpp"

namespace collide::compose {
namespace {

// The labels `frame` shows, by their bodies or in their legends (their slots' keys only).
LabelSlots labelsShown(const frame::FrameModel& frame) {
  LabelSlots keys;
  const auto add = [&keys](std::size_t panel, std::size_t body, bool velocity) {
    LabelSlot key;
    key.panel = panel;
    key.body = body;
    key.velocity = velocity;
    if (findLabel(keys, key) == nullptr) keys.push_back(key);
  };
  for (std::size_t p = 0; p < frame.panels.size(); ++p) {
    const frame::PanelModel& panel = frame.panels[p];
    for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
      if (panel.bodies[i].label_at) add(p, i, false);
      if (panel.bodies[i].velocity_label_at) add(p, i, true);
    }
    for (const frame::ReadoutLegend::Entry& entry : panel.legend.entries) {
      add(p, static_cast<std::size_t>(std::max(0, entry.body)), !entry.mass);
    }
  }
  return keys;
}

// Where `frame` shows the label of `key`.
LabelPlace shownAt(const frame::FrameModel& frame, const LabelSlot& key) {
  const frame::BodyModel& body = frame.panels[key.panel].bodies[key.body];
  if (key.velocity ? body.velocity_label_at.has_value() : body.label_at.has_value()) {
    return LabelPlace::kBody;
  }
  return LabelPlace::kLegend;
}

// How far the legend line of `key` moved from the step before (`was`, none at the video's
// start) to this one: beyond the body it rides with, or standing still, whichever is less (a
// line that rides with none, or stands while its body moves on, did not jump), where it is
// listed at both (else 0).
double legendMovedPx(const std::optional<LabelSlot>& was, const std::optional<LabelSlot>& now) {
  if (!now || !was || !now->legend || !was->legend) return 0.0;
  const LegendLine &then = *was->legend, &line = *now->legend;
  // Its left edge, right edge or middle, whichever moved least (shiftAlong): a line whose
  // number grows keeps one of them (a legend flush right keeps its right edge).
  const auto movedFrom = [&](const core::Vec2& carried) {
    const core::Vec2 beyond = carried - then.px;
    return std::hypot(shiftAlong(then.px.x(), then.px.x() + then.width_px, line.px.x(),
                                 line.px.x() + line.width_px, beyond.x()),
                      line.px.y() - carried.y());
  };
  const double stood_px = movedFrom(then.px);
  if (!(then.by >= 0 && then.by == line.by)) return stood_px;
  return std::min(stood_px, movedFrom(then.px + (line.by_px - then.by_px)));
}

// The box a placed text covers.
Box textBox(const frame::PlacedText& text) {
  const core::Vec2 corner = text.top_left_px;
  return {corner.x(), corner.y(), corner.x() + text.size_px.x(), corner.y() + text.size_px.y()};
}

// Puts the label of `slot` (placed off its way in `frame`, by its body) back on its way where
// it is fading in or out there (0 < `opacity` < 1), and says whether it did. A frame between two
// steps where an arrow changes its form touches it there (billiards-follow 640x360 at 0.383 s:
// ball 1's arrow lifted into its row beside the fading "m₁"): it holds its place, as faint as its
// fade has it, for that frame, rather than vanish in the middle of its fade and come back a
// frame later; shifted by the least of kHoldShiftsPx that `free_at` finds free (at most a
// standing text's 2 px from frame to frame), else not held.
constexpr std::array<double, 4> kHoldShiftsPx = {0.0, 0.5, 1.0, 1.5};
bool holdsItsWayMidFade(frame::FrameModel& frame, const LabelSlot& slot, double opacity,
                        const std::function<bool(const LabelSlot&, const Box&)>& free_at) {
  if (!(opacity > 0.0 && opacity < 1.0) || !slot.wanted_px) return false;
  frame::BodyModel& body = frame.panels[slot.panel].bodies[slot.body];
  std::optional<frame::PlacedText>& at = slot.velocity ? body.velocity_label_at : body.label_at;
  if (!at) return false;
  for (const double by : kHoldShiftsPx) {
    for (const core::Vec2& shift :
         {core::Vec2{-by, 0.0}, core::Vec2{by, 0.0}, core::Vec2{0.0, -by}, core::Vec2{0.0, by}}) {
      const core::Vec2 corner = *slot.wanted_px + shift;
      const Box box{corner.x(), corner.y(), corner.x() + at->size_px.x(),
                    corner.y() + at->size_px.y()};
      if (!free_at(slot, box)) continue;
      at->top_left_px = corner;
      at->leader_to_px.reset();
      return true;
    }
  }
  return false;
}

// The most steps placesOf keeps the places of (all its answers together): a few shots' labels,
// the frames of a long video asking for the same ones in turn.
constexpr std::size_t kMostPlacesKept = 1 << 18;
// The most steps shownOf keeps what the frames show at (all shots together): the shots around
// the frames being made, a long video's earlier ones let go.
constexpr std::size_t kMostShownKept = 1 << 14;

}  // namespace

void LabelTimeline::place(frame::FrameModel& frame, double t_s) {
  const LabelSlots off_their_ways = placeOnWays(frame, t_s);
  // The shots from two fades before t_s to two fades after it, each whole: far enough to see
  // whether a stay next to a change lasts a fade, and every stay's shot (hideShortStays). Not
  // farther ahead: the shot after may be minutes long (a scene run for 600 s), and a frame
  // would wait for all of it to be walked.
  const std::size_t first = shotAt(std::max(0.0, t_s - 2.0 * kFade_s));
  const std::size_t last = shotAt(std::min(duration_s_, t_s + 2.0 * kFade_s));
  const double playback_s = picture_.playback_at ? picture_.playback_at(t_s) : t_s;
  // What a place costs in this frame, asked only where a label is held on its way.
  std::optional<LabelProbe> probe;
  const auto free_at = [&](const LabelSlot& slot, const Box& box) {
    if (!probe) probe.emplace(picture_.probe(picture_.compose(t_s)));
    const Label* label = probe->label(slot.panel, slot.body, slot.velocity);
    return label != nullptr && probe->cost(slot.panel, *label, box, -1) < kHard;
  };
  for (const LabelSlot& key : labelsShown(frame)) {
    if (key.body >= frame.panels[key.panel].bodies.size()) continue;
    const std::shared_ptr<const std::vector<PlaceAtStep>> places =
        placesOf(key, key.velocity ? Placed::kVelocity : Placed::kMass, first, last);
    double opacity = placeOpacity(*places, first == 0, shownAt(frame, key), t_s, playback_s);
    // Placed off its way between two steps (the steps' frames, shownOf, are on the plan or
    // are places of their own): not seen for that frame rather than seen leaping there and back,
    // unless it is fading there (holdsItsWayMidFade).
    if (const LabelSlot* off = findLabel(off_their_ways, key)) {
      if (!holdsItsWayMidFade(frame, *off, opacity, free_at)) opacity = 0.0;
    }
    if (opacity < 1.0) {
      fadeLabel(frame, key.panel, key.body, key.velocity, static_cast<float>(opacity));
    }
  }
  fadeNumbers(frame);
  fadeArrowTags(frame, first, last, t_s, playback_s);
}

void LabelTimeline::fadeArrowTags(frame::FrameModel& frame, std::size_t first, std::size_t last,
                                  double t_s, double playback_s) {
  for (std::size_t p = 0; p < frame.panels.size(); ++p) {
    std::vector<frame::BodyModel>& bodies = frame.panels[p].bodies;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      if (!bodies[i].arrow_tag_at) continue;
      LabelSlot key;
      key.panel = p;
      key.body = i;
      const std::shared_ptr<const std::vector<PlaceAtStep>> places =
          placesOf(key, Placed::kArrowTag, first, last);
      const double opacity = placeOpacity(*places, first == 0, LabelPlace::kBody, t_s, playback_s);
      bodies[i].arrow_tag_at->opacity = static_cast<float>(opacity);
    }
  }
}

std::shared_ptr<const std::vector<PlaceAtStep>> LabelTimeline::placesOf(const LabelSlot& key,
                                                                        Placed what,
                                                                        std::size_t first,
                                                                        std::size_t last) {
  const PlacesKey at{key.panel, key.body, what, first, last};
  {
    const std::lock_guard<std::mutex> lock(places_mutex_);
    const auto found = places_.find(at);
    if (found != places_.end()) return found->second;
  }
  // Found outside the lock (the shots may be walked first); two threads that find one both
  // find the same.
  auto places = std::make_shared<const std::vector<PlaceAtStep>>(
      what == Placed::kArrowTag ? findArrowTagPlaces(key, first, last)
                                : findPlaces(key, first, last));
  const std::lock_guard<std::mutex> lock(places_mutex_);
  if (places_kept_ + places->size() > kMostPlacesKept) {
    places_.clear();
    places_kept_ = 0;
  }
  if (places_.emplace(at, places).second) places_kept_ += places->size();
  return places;
}

std::vector<PlaceAtStep> LabelTimeline::findPlaces(const LabelSlot& key, std::size_t first,
                                                   std::size_t last) {
  std::vector<PlaceAtStep> places;
  const LabelAt* was = nullptr;
  std::optional<LabelSlot> was_listed;
  int place = 0, off_runs = 0;
  for (std::size_t shot = first; shot <= last; ++shot) {
    const std::vector<Step>& steps = walkOf(shot);
    const std::shared_ptr<const ShownSteps> shown = shownOf(shot);
    for (std::size_t k = 0; k < steps.size(); ++k) {
      const LabelAt* now = findLabel(steps[k].placed, key);
      // As jumpingWays counts a jump: farther beyond its body than a glide from step to step.
      if (now != nullptr && was && now->movedFrom(*was) > jumpPxAt(steps[k].t_s, now->two_d)) {
        ++place;
      }
      const std::optional<LabelSlot> listed = listedAt(steps, k, key);
      const LabelPlace at = now != nullptr ? LabelPlace::kBody
                            : listed       ? LabelPlace::kLegend
                                           : LabelPlace::kNowhere;
      // A legend that moves (rearranged, or crossed by a ball) jumps like a label by its body,
      // at an event too.
      if (at == LabelPlace::kLegend &&
          legendMovedPx(was_listed, listed) > jumpPxAt(steps[k].t_s, steps[k].two_d)) {
        ++place;
      }
      was_listed = listed;
      PlaceAtStep step{steps[k].t_s, at, k == 0 && shot > 0,
                       at != LabelPlace::kNowhere ? place : 0};
      // Where the frame shows it elsewhere, that is where it is seen: a place of its own.
      if (const std::optional<LabelPlace> seen = offPlan(steps, k, (*shown)[k].labels, key, at)) {
        if (places.empty() || !places.back().off_plan) ++off_runs;
        step.at = *seen;
        step.place = -off_runs;
        step.off_plan = true;
      }
      step.playback_s = picture_.playback_at ? picture_.playback_at(step.t_s) : step.t_s;
      places.push_back(step);
      was = now;
    }
  }
  hideShortStays(places, first == 0, last + 1 == shot_starts_s_.size());
  return places;
}

std::vector<PlaceAtStep> LabelTimeline::findArrowTagPlaces(const LabelSlot& key, std::size_t first,
                                                           std::size_t last) {
  std::vector<PlaceAtStep> places;
  std::optional<ShownTag> was;  // a copy: the shot before's steps may be let go
  int place = 0;
  for (std::size_t shot = first; shot <= last; ++shot) {
    const std::vector<Step>& steps = walkOf(shot);
    const std::shared_ptr<const ShownSteps> shown = shownOf(shot);
    for (std::size_t k = 0; k < steps.size(); ++k) {
      const ShownTag* now = nullptr;
      for (const ShownTag& tag : (*shown)[k].arrow_tags) {
        if (tag.panel == key.panel && tag.body == key.body) now = &tag;
      }
      // As a label's way jumps: farther beyond its body (or standing) than a glide, across an
      // event too (its lifted arrow comes down or goes up there, and the number with it).
      if (now != nullptr && was &&
          moveBetween(was->box, was->body_px, now->box, now->body_px).px >
              jumpPxAt(steps[k].t_s, steps[k].two_d)) {
        ++place;
      }
      PlaceAtStep step{steps[k].t_s, now != nullptr ? LabelPlace::kBody : LabelPlace::kNowhere,
                       k == 0 && shot > 0, now != nullptr ? place : 0};
      step.playback_s = picture_.playback_at ? picture_.playback_at(step.t_s) : step.t_s;
      places.push_back(step);
      was = now != nullptr ? std::optional<ShownTag>(*now) : std::nullopt;
    }
  }
  hideShortStays(places, first == 0, last + 1 == shot_starts_s_.size());
  return places;
}

std::shared_ptr<const LabelTimeline::ShownSteps> LabelTimeline::shownOf(std::size_t shot) {
  {
    const std::lock_guard<std::mutex> lock(shown_mutex_);
    const auto found = shown_.find(shot);
    if (found != shown_.end()) return found->second;
  }
  const std::vector<Step>& steps = walkOf(shot);
  auto shown = std::make_shared<ShownSteps>();
  for (const Step& step : steps) {
    frame::FrameModel frame = picture_.compose(step.t_s);
    placeOnWays(frame, step.t_s);
    ShownStep& seen = shown->emplace_back();
    std::vector<ShownLabel>& labels = seen.labels;
    const std::vector<std::vector<core::Vec2>> body_px = picture_.body_px(frame);
    for (std::size_t p = 0; p < frame.panels.size(); ++p) {
      const frame::PanelModel& panel = frame.panels[p];
      for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
        if (const std::optional<frame::PlacedText>& tag = panel.bodies[i].arrow_tag_at;
            tag && p < body_px.size() && i < body_px[p].size()) {
          seen.arrow_tags.push_back({p, i, textBox(*tag), body_px[p][i]});
        }
        for (const bool velocity : {false, true}) {
          const std::optional<frame::PlacedText>& at =
              velocity ? panel.bodies[i].velocity_label_at : panel.bodies[i].label_at;
          if (!at) continue;
          labels.push_back({p, i, velocity, LabelPlace::kBody, textBox(*at)});
        }
      }
      for (const frame::ReadoutLegend::Entry& entry : panel.legend.entries) {
        const core::Vec2 corner = entry.top_left_px;
        labels.push_back({p, static_cast<std::size_t>(std::max(0, entry.body)), !entry.mass,
                          LabelPlace::kLegend,
                          Box{corner.x(), corner.y(), corner.x(), corner.y()}});
      }
    }
  }
  const std::lock_guard<std::mutex> lock(shown_mutex_);
  if (shown_kept_ + shown->size() > kMostShownKept) {
    shown_.clear();
    shown_kept_ = 0;
  }
  const auto [at, added] = shown_.emplace(shot, std::move(shown));
  if (added) shown_kept_ += at->second->size();
  return at->second;
}

std::optional<LabelPlace> LabelTimeline::offPlan(const std::vector<Step>& steps, std::size_t k,
                                                 const std::vector<ShownLabel>& shown,
                                                 const LabelSlot& key, LabelPlace planned) const {
  if (planned == LabelPlace::kNowhere) return std::nullopt;
  const ShownLabel* seen = nullptr;
  for (const ShownLabel& label : shown) {
    if (label.panel == key.panel && label.body == key.body && label.velocity == key.velocity) {
      seen = &label;
    }
  }
  if (seen == nullptr) return LabelPlace::kNowhere;
  if (seen->at != planned) return seen->at;
  const double jump_px = jumpPxAt(steps[k].t_s, steps[k].two_d);
  if (planned == LabelPlace::kBody) {
    const LabelAt& plan = *findLabel(steps[k].placed, key);
    const Move moved = moveBetween(plan.shownBox(), plan.body_px, seen->box, plan.body_px);
    return moved.px > jump_px ? std::optional<LabelPlace>(seen->at) : std::nullopt;
  }
  const std::optional<LabelSlot> listed = listedAt(steps, k, key);
  if (!listed || !listed->legend) return std::nullopt;
  const core::Vec2 corner{seen->box.x0, seen->box.y0};
  return (corner - listed->legend->px).norm() > jump_px ? std::optional<LabelPlace>(seen->at)
                                                        : std::nullopt;
}

}  // namespace collide::compose
