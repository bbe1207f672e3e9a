// SPDX-License-Identifier: MIT
#include "arrow_form_checks.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace collide::test {
namespace {

// A tail this far off its body's centre, pixels, stands off it (a painter's round-off is far less;
// an arrow from the edge or beside a body stands a radius off).
constexpr double kOffCentrePx = 1.0;

core::Vec2 boxCentre(const frame::PixelRect& box) {
  return {0.5 * (box.x0 + box.x1), 0.5 * (box.y0 + box.y1)};
}

std::string formOf(const frame::DrawnArrow& arrow, const frame::PixelRect* body, bool two_d) {
  if (arrow.drawn == frame::ArrowDrawn::kBelowScale) return "below scale";
  if (arrow.drawn == frame::ArrowDrawn::kOffScale) return "off scale";
  if (!two_d || body == nullptr) return "on scale";
  const core::Vec2 along = (arrow.to_px - arrow.from_px).normalized();
  const core::Vec2 tail = arrow.from_px - boxCentre(*body);
  const double across_px = along.x() * tail.y() - along.y() * tail.x();
  if (std::abs(across_px) > kOffCentrePx) return "beside";
  if (along.dot(tail) > kOffCentrePx) return "from the edge";
  return "from the centre";
}

// How long a form says its arrow is: none, a below-scale mark, on its scale (from the centre,
// the edge or beside), off its scale.
int lengthRank(const std::string& form) {
  if (form == "none") return 0;
  if (form == "below scale") return 1;
  return form == "off scale" ? 3 : 2;
}

// Whether the change between the form of `run` and that of `next` is its speed's: one says a
// longer arrow than the other where its speed is higher.
template <typename Seen>
bool changeBySpeed(const Seen& run, const Seen& next) {
  const int ranks = lengthRank(run.at.form) - lengthRank(next.at.form);
  const double faster = run.at.speed_mps - next.at.speed_mps;
  return (ranks < 0 && faster < 0.0) || (ranks > 0 && faster > 0.0);
}

// Whether both changes of form around seen[first, last] are its speed's, in every frame of it.
template <typename Seen>
bool changesBySpeed(const std::vector<Seen>& seen, std::size_t first, std::size_t last) {
  for (std::size_t k = first; k <= last; ++k) {
    if (!changeBySpeed(seen[k], seen[first - 1]) || !changeBySpeed(seen[k], seen[last + 1])) {
      return false;
    }
  }
  return true;
}

}  // namespace

ArrowFormsAt arrowFormsAt(const frame::FrameModel& model,
                          const std::vector<frame::DrawnItem>& items) {
  ArrowFormsAt forms;
  for (std::size_t p = 0; p < model.panels.size(); ++p) {
    for (std::size_t b = 0; b < model.panels[p].bodies.size(); ++b) {
      forms[{static_cast<int>(p), static_cast<int>(b)}] = {
          "none", model.panels[p].bodies[b].velocity_mps.norm()};
    }
  }
  std::map<std::pair<int, int>, const frame::PixelRect*> bodies;
  for (const frame::DrawnItem& item : items) {
    if (item.kind == "body" && item.body >= 0) bodies[{item.panel, item.body}] = &item.box;
  }
  for (const frame::DrawnItem& item : items) {
    if (item.kind != "arrow" || !item.arrow || item.body < 0 || item.panel < 0) continue;
    const auto at = forms.find({item.panel, item.body});
    if (at == forms.end()) continue;
    const auto body = bodies.find({item.panel, item.body});
    at->second.form = formOf(*item.arrow, body != bodies.end() ? body->second : nullptr,
                             model.panels[static_cast<std::size_t>(item.panel)].two_d);
  }
  return forms;
}

void ArrowFormWatch::add(double t_s, const ArrowFormsAt& forms, bool after_event) {
  if (after_event) endStretch();
  for (const auto& [key, at] : forms) stretch_[key].push_back({t_s, at});
}

std::vector<std::string> ArrowFormWatch::finish() {
  endStretch();
  return std::move(found_);
}

void ArrowFormWatch::endStretch() {
  for (const auto& [key, seen] : stretch_) {
    // Each run of one form that a change begins and a change ends (not an event, nor the video's
    // first or last frame).
    std::size_t first = 0;
    for (std::size_t k = 1; k < seen.size(); ++k) {
      if (seen[k].at.form == seen[k - 1].at.form) continue;
      const std::size_t last = k - 1;
      if (first > 0 && static_cast<int>(k - first) < kFewestFormFrames) {
        const std::string& form = seen[first].at.form;
        if (!changesBySpeed(seen, first, last)) {
          std::ostringstream line;
          line << (key.first > 0 ? "panel" + std::to_string(key.first + 1) + "." : "") << "arrow."
               << key.second + 1 << " is " << form << " for " << k - first
               << " frame(s) from t = " << seen[first].t_s << " s (" << seen[first - 1].at.form
               << " before, " << seen[k].at.form << " after)";
          found_.push_back(line.str());
        }
      }
      first = k;
    }
  }
  stretch_.clear();
}

}  // namespace collide::test
