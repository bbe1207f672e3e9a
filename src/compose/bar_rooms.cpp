// SPDX-License-Identifier: MIT
#include "compose/bar_rooms.hpp"

#include <algorithm>

#include "compose/readouts.hpp"

namespace collide::compose {
namespace {

constexpr int kRoomEvenSamples = 400;          // evenly spaced instants over the run
constexpr std::size_t kRoomMostEvents = 2000;  // collisions and soft contacts sampled, at most each
// Labels are compared at this size: widths scale with it, so the widest is the same at any.
constexpr double kRoomCompare_px = 100.0;

std::vector<double> roomSampleTimes(const physics::Timeline& timeline) {
  std::vector<double> times;
  const double duration_s = timeline.duration_s();
  for (int i = 0; i <= kRoomEvenSamples; ++i) times.push_back(duration_s * i / kRoomEvenSamples);
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

std::vector<std::string> planBarRooms(const scene::SceneDesc& scene,
                                      const physics::Timeline& timeline, const FramePlan& plan,
                                      const Theme& theme, const text::TextWidth& width) {
  std::vector<std::string> rooms;
  std::vector<double> room_px;
  FramePlan unplanned = plan;
  unplanned.bar_rooms.clear();
  for (const double t_s : roomSampleTimes(timeline)) {
    const physics::EnergyBooks books = panelBooks(timeline, unplanned, t_s);
    const frame::EnergyBar bar = energyBar(scene, unplanned, theme, books,
                                           spinEnergies_J(scene, timeline, unplanned, books));
    // The same parts at every instant (energyBar): a count that differs is not planned.
    if (!rooms.empty() && bar.segments.size() != rooms.size()) return {};
    rooms.resize(bar.segments.size());
    room_px.resize(bar.segments.size(), 0.0);
    for (std::size_t k = 0; k < bar.segments.size(); ++k) {
      const std::string& label = bar.segments[k].label;
      if (label.empty()) continue;
      const double px = width(label, kRoomCompare_px);
      if (rooms[k].empty() || px > room_px[k]) {
        rooms[k] = label;
        room_px[k] = px;
      }
    }
  }
  return rooms;
}

}  // namespace collide::compose
