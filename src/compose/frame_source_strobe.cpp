// SPDX-License-Identifier: MIT
// FrameSource's stroboscope photograph: its rate, its span, its images and its frame.
#include <algorithm>
#include <vector>

#include "compose/frame_source.hpp"
#include "compose/frame_source_state.hpp"
#include "compose/gas_strobe.hpp"
#include "compose/gas_view.hpp"
#include "compose/strobe_plan.hpp"
#include "compose/strobe_text.hpp"

namespace collide::compose {

namespace {

// The molecules a gas panel's strobe photographs (gas_strobe.hpp); other panels: none, all shown.
std::vector<std::size_t> strobeMarks(const Panel& panel) {
  return isGas(panel.scene) ? markedMolecules(panel.timeline) : std::vector<std::size_t>{};
}

}  // namespace

namespace {

// The strobe's view of each panel; `marks` holds each panel's strobeMarks and must outlive them.
std::vector<StrobeSubject> strobeSubjects(const std::vector<Panel>& panels, const Theme& theme,
                                          std::vector<std::vector<std::size_t>>& marks) {
  marks.clear();
  for (const Panel& panel : panels) marks.push_back(strobeMarks(panel));
  std::vector<StrobeSubject> out;
  for (std::size_t p = 0; p < panels.size(); ++p) {
    const Panel& panel = panels[p];
    out.push_back(
        {panel.scene, panel.timeline, panel.plan, theme, isGas(panel.scene) ? &marks[p] : nullptr});
  }
  return out;
}

}  // namespace

double FrameSource::State::ownStrobeSpan_s() {
  std::call_once(strobe_span_once, [this] {
    std::vector<std::vector<std::size_t>> marks;
    strobe_span_s = compose::strobeSpan_s(strobeSubjects(panels, *theme, marks), scene.duration_s);
  });
  return strobe_span_s;
}

double FrameSource::strobeSpan_s(bool keep_apart) const {
  return keep_apart ? state_->ownStrobeSpan_s() : state_->scene.duration_s;
}

double FrameSource::strobeRate_hz() const {
  const State& s = *state_;
  std::vector<std::vector<std::size_t>> marks;
  const std::vector<StrobeSubject> panels = strobeSubjects(s.panels, *s.theme, marks);
  bool gas = false;
  for (const Panel& panel : s.panels) gas = gas || isGas(panel.scene);
  return chooseStrobeRate_hz(panels, state_->ownStrobeSpan_s(),
                             gas ? kGasStrobeMaxImages : kMaxStrobeImages);
}

int FrameSource::strobeImages(double rate_hz, bool keep_apart) const {
  return std::min(kMaxStrobeImages, strobeImageCount(strobeSpan_s(keep_apart), rate_hz));
}

frame::FrameModel FrameSource::strobeFrame(double rate_hz, bool keep_apart) const {
  const State& s = *state_;
  const double duration = strobeSpan_s(keep_apart);
  if (!(rate_hz > 0.0)) rate_hz = strobeRate_hz();
  frame::FrameModel frame = state_->frameAt(duration, true);
  // A photograph of the whole run: its whole working, as the video's last frame shows it.
  if (frame.working) frame.working->shown_lines = -1;
  frame.charts.clear();
  frame.subtitle.clear();
  frame.time_readout = strobeSpanText(duration, s.panels.front().plan.formats.time);
  const int images = std::min(kMaxStrobeImages, strobeImageCount(duration, rate_hz));
  for (std::size_t p = 0; p < s.panels.size(); ++p) {
    const Panel& panel = s.panels[p];
    frame::PanelModel& out = frame.panels[p];
    const bool gas = isGas(panel.scene);
    const std::vector<std::size_t> marked = strobeMarks(panel);
    StrobeImages ghosts =
        strobeGhosts({panel.scene, panel.timeline, panel.plan, *s.theme, gas ? &marked : nullptr},
                     duration, rate_hz, out.bodies, keep_apart);
    if (gas) {
      // Each marked molecule in its own colour, its images fading like any strobe's.
      for (std::size_t g = 0; g < ghosts.ghosts.size(); ++g) {
        const auto k = static_cast<std::size_t>(
            std::find(marked.begin(), marked.end(), ghosts.ghost_bodies[g]) - marked.begin());
        const float alpha = ghosts.ghosts[g].fill.a;
        ghosts.ghosts[g].fill = markedColour(*s.theme, k);
        ghosts.ghosts[g].fill.a *= alpha;
      }
    }
    out.ghosts = std::move(ghosts.ghosts);
    // The last image solid, with its labels but no arrows: a photograph shows no velocities.
    out.arrow_m_per_mps = 0.0;
    out.scale_arrow_mps = 0.0;
    out.scale_arrow_label.clear();
    out.flashes.clear();
    out.momentum.reset();
    out.show_energy_bar = false;
    for (frame::BodyModel& body : out.bodies) {
      body.velocity_label.clear();
      body.trail_m.clear();
    }
    // Nor the legend's readouts, which placement would give back to the bodies: the end's
    // velocities by the images read as the velocities there (granular-chain's strobe).
    std::erase_if(out.legend.entries,
                  [](const frame::ReadoutLegend::Entry& entry) { return !entry.mass; });
    if (gas)
      markGasStrobe(out, marked, panel.scene, panel.timeline, panel.plan, *s.theme, duration);
    out.caption = strobeCaption(rate_hz, images, ghosts.moving_left_out, gas, ghosts.impacts_shown,
                                strobeRelease(panel.timeline, duration, panel.plan.formats.time),
                                ghosts.releases_shown);
  }
  state_->place(frame);
  return frame;
}

}  // namespace collide::compose
