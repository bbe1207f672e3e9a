// SPDX-License-Identifier: MIT
#include "compose/bar_rooms.hpp"

#include <algorithm>

#include "compose/label_timeline.hpp"
#include "compose/readouts.hpp"

namespace collide::compose {
namespace {

constexpr int kRoomEvenSamples = 400;          // evenly spaced instants over the run
constexpr int kShotSamples = 12;               // evenly spaced instants in each shot, at least
constexpr int kMostShotSamples = 400;          // ... unless the shots together would take more
constexpr std::size_t kRoomMostEvents = 2000;  // collisions and soft contacts sampled, at most each
// Labels are compared at this size: widths scale with it, so the widest is the same at any.
constexpr double kRoomCompare_px = 100.0;

std::vector<double> roomSampleTimes(const physics::Timeline& timeline,
                                    const std::vector<double>& shot_starts_s) {
  std::vector<double> times;
  const double duration_s = timeline.duration_s();
  for (int i = 0; i <= kRoomEvenSamples; ++i) times.push_back(duration_s * i / kRoomEvenSamples);
  const int per_shot = std::max(
      2, std::min(kShotSamples, kMostShotSamples / std::max<int>(1, shot_starts_s.size())));
  for (std::size_t s = 0; s < shot_starts_s.size(); ++s) {
    const double from_s = shot_starts_s[s];
    const double to_s = s + 1 < shot_starts_s.size() ? shot_starts_s[s + 1] : duration_s;
    for (int i = 0; i < per_shot && from_s < to_s; ++i) {
      times.push_back(from_s + (to_s - from_s) * i / per_shot);
    }
  }
  const std::vector<physics::CollisionEvent>& events = timeline.collisions();
  for (std::size_t k = 0; k < events.size() && k < kRoomMostEvents; ++k) {
    times.push_back(events[k].time_s);
  }
  const std::vector<physics::SoftContact>& contacts = timeline.softContacts();
  for (std::size_t k = 0; k < contacts.size() && k < kRoomMostEvents; ++k) {
    times.push_back(0.5 * (contacts[k].start_s + contacts[k].end_s));
  }
  return times;
}

}  // namespace

void planBarLegend(const scene::SceneDesc& scene, const physics::Timeline& timeline,
                   FramePlan& plan, const Theme& theme, const text::TextWidth& width,
                   const std::vector<double>& shot_starts_s) {
  FramePlan unplanned = plan;
  unplanned.bar_rooms.clear();
  unplanned.bar_shots = {{shot_starts_s.empty() ? std::vector<double>{0.0} : shot_starts_s}, {}};
  const std::vector<double> times = roomSampleTimes(timeline, unplanned.bar_shots.starts_s);
  const auto barAt = [&](double t_s) {
    const physics::EnergyBooks books = panelBooks(timeline, unplanned, t_s);
    return energyBar(scene, unplanned, theme, books,
                     spinEnergies_J(scene, timeline, unplanned, books));
  };
  // First what each shot labels and the widest labels, then the labels of the entries kept
  // through their shots where they were left out (a kept entry's small value may be its widest).
  FramePlan::BarShots shots{unplanned.bar_shots.starts_s, {}};
  std::vector<frame::EnergyBar> bars;
  for (const double t_s : times) {
    bars.push_back(barAt(t_s));
    // The same parts at every instant (energyBar): a count that differs is not planned.
    const std::size_t segments = bars.back().segments.size();
    if (segments != bars.front().segments.size()) return;
    shots.shown.resize(shots.starts_s.size(), std::vector<bool>(segments, false));
    std::vector<bool>& shown = shots.shown[shotOf(shots.starts_s, t_s)];
    for (std::size_t k = 0; k < segments; ++k) {
      if (!bars.back().segments[k].label.empty()) shown[k] = true;
    }
  }
  unplanned.bar_shots = shots;
  for (std::size_t i = 0; i < times.size(); ++i) {
    const std::vector<bool>& shown = shots.shown[shotOf(shots.starts_s, times[i])];
    for (std::size_t k = 0; k < shown.size(); ++k) {
      const frame::EnergySegment& segment = bars[i].segments[k];
      if (shown[k] && segment.label.empty() &&
          segment.energy_J > kLabelledShare * unplanned.energy_full_scale_J) {
        bars[i] = barAt(times[i]);
        break;
      }
    }
  }
  const std::size_t segments = bars.empty() ? 0 : bars.front().segments.size();
  std::vector<std::string> rooms(segments);
  std::vector<double> room_px(segments, 0.0);
  for (const frame::EnergyBar& bar : bars) {
    for (std::size_t k = 0; k < segments; ++k) {
      const std::string& label = bar.segments[k].label;
      if (label.empty()) continue;
      const double px = width(label, kRoomCompare_px);
      if (rooms[k].empty() || px > room_px[k]) {
        rooms[k] = label;
        room_px[k] = px;
      }
    }
  }
  plan.bar_rooms = std::move(rooms);
  plan.bar_shots = std::move(shots);
}

}  // namespace collide::compose
