// SPDX-License-Identifier: MIT
#include "legend_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <optional>
#include <sstream>
#include <utility>

#include "render/frame_layout.hpp"
#include "video_frame_checks.hpp"

namespace collide::test {
namespace {

// An energy of a segment this small a share of the bar's full scale is round-off of none.
constexpr double kZeroShare = 1e-9;
// A leader ends on its entry: its last point within this of the entry's box, pixels.
constexpr double kOnEntryPx = 1.0;

double cross(const core::Vec2& a, const core::Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

bool within(const core::Vec2& p, const core::Vec2& q, const core::Vec2& r) {
  return std::min(p.x(), q.x()) <= r.x() && r.x() <= std::max(p.x(), q.x()) &&
         std::min(p.y(), q.y()) <= r.y() && r.y() <= std::max(p.y(), q.y());
}

// Whether the segments ab and cd cross or touch.
bool segmentsMeet(const core::Vec2& a, const core::Vec2& b, const core::Vec2& c,
                  const core::Vec2& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  if (((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) &&
      ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0))) {
    return true;
  }
  return (d1 == 0.0 && within(a, b, c)) || (d2 == 0.0 && within(a, b, d)) ||
         (d3 == 0.0 && within(c, d, a)) || (d4 == 0.0 && within(c, d, b));
}

// Whether the segment ab passes inside `box` (sampled every half pixel).
bool segmentInBox(const core::Vec2& a, const core::Vec2& b, const frame::PixelRect& box) {
  const int samples = std::max(2, static_cast<int>(2.0 * (b - a).norm()));
  for (int k = 0; k <= samples; ++k) {
    const core::Vec2 p = a + (b - a) * (static_cast<double>(k) / samples);
    if (p.x() > box.x0 && p.x() < box.x1 && p.y() > box.y0 && p.y() < box.y1) return true;
  }
  return false;
}

bool pathsMeet(const std::vector<core::Vec2>& p, const std::vector<core::Vec2>& q) {
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    for (std::size_t j = 0; j + 1 < q.size(); ++j) {
      if (segmentsMeet(p[i], p[i + 1], q[j], q[j + 1])) return true;
    }
  }
  return false;
}

bool pathInBox(const std::vector<core::Vec2>& p, const frame::PixelRect& box) {
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    if (segmentInBox(p[i], p[i + 1], box)) return true;
  }
  return false;
}

std::string describe(const std::vector<core::Vec2>& path) {
  std::ostringstream out;
  for (const core::Vec2& p : path) out << " (" << p.x() << ", " << p.y() << ")";
  return out.str();
}

// A panel's legend: its entries' boxes and its leaders' paths, by the entry's id.
struct Legend {
  std::map<std::string, frame::PixelRect> entries;
  std::map<std::string, std::vector<core::Vec2>> leaders;
};

std::map<int, Legend> legends(const std::vector<frame::DrawnItem>& items) {
  std::map<int, Legend> out;
  for (const frame::DrawnItem& item : items) {
    const std::size_t at = item.id.find("energy.");
    if (at == std::string::npos) continue;
    const std::string prefix = item.id.substr(0, at);
    if (prefix.empty() || prefix.back() == '.') {
      out[item.panel].entries[item.id] = item.box;
    } else if (prefix.size() >= 7 && prefix.compare(prefix.size() - 7, 7, "leader.") == 0) {
      out[item.panel].leaders[prefix.substr(0, prefix.size() - 7) + item.id.substr(at)] = item.path;
    }
  }
  return out;
}

}  // namespace

std::string tangledLeader(const std::vector<frame::DrawnItem>& items) {
  for (const auto& [panel, legend] : legends(items)) {
    for (const auto& [id, path] : legend.leaders) {
      const auto own = legend.entries.find(id);
      if (path.size() < 2 || own == legend.entries.end()) return id + "'s leader has no entry";
      const frame::PixelRect& box = own->second;
      const core::Vec2& end = path.back();
      if (end.x() < box.x0 - kOnEntryPx || end.x() > box.x1 + kOnEntryPx ||
          end.y() < box.y0 - kOnEntryPx || end.y() > box.y1 + kOnEntryPx) {
        return id + "'s leader ends off its entry:" + describe(path);
      }
      for (const auto& [other, other_path] : legend.leaders) {
        if (other > id && pathsMeet(path, other_path)) {
          return id + "'s leader meets " + other + "'s:" + describe(path) + " and" +
                 describe(other_path);
        }
      }
      for (const auto& [other, other_box] : legend.entries) {
        if (other != id && pathInBox(path, other_box)) {
          return id + "'s leader runs through " + other + ":" + describe(path);
        }
      }
    }
  }
  return "";
}

std::vector<std::string> entriesThatComeAndGo(const frame::FrameModel& was,
                                              const frame::FrameModel& now) {
  std::vector<std::string> found;
  for (std::size_t p = 0; p < was.panels.size() && p < now.panels.size(); ++p) {
    const frame::EnergyBar& a = was.panels[p].energy_bar;
    const frame::EnergyBar& b = now.panels[p].energy_bar;
    for (std::size_t k = 0; k < a.segments.size() && k < b.segments.size(); ++k) {
      const frame::EnergySegment& before = a.segments[k];
      const frame::EnergySegment& after = b.segments[k];
      if (before.label.empty() == after.label.empty()) continue;
      if (before.energy_J <= kZeroShare * a.full_scale_J ||
          after.energy_J <= kZeroShare * b.full_scale_J) {
        continue;
      }
      found.push_back("panel " + std::to_string(p + 1) + " entry " + std::to_string(k + 1) +
                      (after.label.empty() ? " vanishes (was \"" + before.label + "\")"
                                           : " appears (\"" + after.label + "\")"));
    }
  }
  return found;
}

LegendWatch watchLegend(const compose::FrameSource& source, double from_s, double to_s,
                        double limit_px, int width_px, int height_px, const std::string& kind) {
  constexpr int kFps = 60;
  LegendWatch watch;
  std::optional<FrameItems> was;
  const int last = static_cast<int>(source.duration_s() * kFps);
  for (int k = 0; k <= last; ++k) {
    const double t_s = source.simulatedAt(double(k) / kFps);
    if (t_s > to_s) break;
    if (t_s < from_s) continue;
    FrameItems now =
        frameItems(t_s, render::drawnItems(source.frameAt(double(k) / kFps), width_px, height_px));
    std::erase_if(now.texts, [&](const auto& text) { return text.second.kind != kind; });
    watch.listed_frames += now.texts.empty() ? 0 : 1;
    if (was) {
      for (std::string& jump : textsThatJump(*was, now, limit_px, TextsOf::kBodies)) {
        watch.jumps.push_back(std::move(jump));
      }
    }
    was = std::move(now);
  }
  return watch;
}

}  // namespace collide::test
