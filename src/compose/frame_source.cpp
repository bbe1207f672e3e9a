#include "compose/frame_source.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <vector>

#include "compose/bar_rooms.hpp"
#include "compose/chart_builder.hpp"
#include "compose/frame_builder.hpp"
#include "compose/frame_source_state.hpp"
#include "compose/frame_text.hpp"
#include "compose/gas_strobe.hpp"
#include "compose/gas_view.hpp"
#include "compose/label_fades.hpp"
#include "compose/label_placement.hpp"
#include "compose/label_timeline.hpp"
#include "compose/palette.hpp"
#include "compose/scale_arrow.hpp"
#include "compose/slow_motion.hpp"
#include "compose/speed_histogram.hpp"
#include "compose/strobe_plan.hpp"
#include "compose/strobe_text.hpp"
#include "compose/text_patterns.hpp"
#include "compose/working_panel.hpp"
#include "core/error.hpp"
#include "frame/layout.hpp"
#include "scene/scene_io.hpp"
#include "text/language.hpp"
#include "text/translate.hpp"
#include "text/wording.hpp"

namespace collide::compose {
namespace {

// Each panel's bar legend in the picture's formats, planned over the whole run (bar_rooms.hpp).
void planBarLegends(std::vector<Panel>& panels, const Theme& theme, text::TextMeasure& metrics,
                    const std::vector<double>& shot_starts_s) {
  const text::TextWidth width = [&metrics](std::string_view text, double px) {
    return metrics.width(text, px);
  };
  for (Panel& panel : panels) {
    planBarLegend(panel.scene, panel.timeline, panel.plan, theme, width, shot_starts_s);
  }
}

Panel makePanel(SimulatedPanel simulated) {
  FramePlan plan = planFrames(simulated.panel.scene, simulated.timeline);
  return Panel{std::move(simulated.panel.scene), std::move(simulated.timeline), std::move(plan),
               std::move(simulated.panel.heading)};
}

// Time-aligned panels share one camera and arrow scale, so they compare at a glance.
void shareOneCamera(std::vector<Panel>& panels) {
  // The scale is the panel's whose fastest arrow needs the most room.
  frame::ViewWindow shared = panels.front().plan.view;
  const FramePlan* scale = &panels.front().plan;
  double off_scale_length_m = 0.0;
  for (const Panel& panel : panels) {
    shared.min_m = shared.min_m.cwiseMin(panel.plan.view.min_m);
    shared.max_m = shared.max_m.cwiseMax(panel.plan.view.max_m);
    if (panel.plan.arrow_m_per_mps > 0.0 &&
        (scale->arrow_m_per_mps <= 0.0 || panel.plan.arrow_m_per_mps < scale->arrow_m_per_mps)) {
      scale = &panel.plan;
    }
    off_scale_length_m = std::max(off_scale_length_m, panel.plan.arrow_max_length_m);
  }
  const double arrow = scale->arrow_m_per_mps, scale_arrow = scale->scale_arrow_mps;
  for (Panel& panel : panels) {
    panel.plan.view = shared;
    panel.plan.arrow_m_per_mps = arrow;
    panel.plan.scale_arrow_mps = scale_arrow;
    panel.plan.arrow_max_length_m = off_scale_length_m;
  }
}

}  // namespace

std::vector<PanelScene> panelScenes(const scene::SceneDesc& scene) {
  if (scene.view.panel_values.empty()) return {PanelScene{scene, ""}};
  std::vector<PanelScene> panels;
  for (scene::SceneVariant& variant : scene::panelVariants(scene)) {
    panels.push_back(
        {std::move(variant.scene), panelHeading(scene.view.panel_parameter, variant.value)});
  }
  return panels;
}

// A video's subtitle while it plays slower than real time ("slow motion ×4").
std::string slowMotionSubtitle(const std::string& factor) {
  // TRANSLATORS: a video's subtitle while it plays slower than real time; {factor} is "×4".
  return text::fill(text::tr("slow motion {factor}"), {{"factor", "×" + factor}});
}

// The widest slow-motion subtitle a video shows: the widest factor it shows and a digit more;
// empty where it plays at its own speed throughout.
std::string subtitleRoom(const scene::ViewDesc& view, const std::vector<double>& collision_times) {
  if (!(view.slow_motion_factor > 1.05) || collision_times.empty()) return {};
  return slowMotionSubtitle(text::formatPlain(view.slow_motion_factor, text::defaultStyle(), 2) +
                            "8");
}

std::vector<std::vector<core::Vec2>> FrameSource::State::bodyPixels(
    const frame::FrameModel& frame) {
  const std::lock_guard<std::mutex> lock(metrics_mutex);
  const frame::FrameLayout layout = frame::layoutFrame(
      frame, size.width_px, size.height_px, size.text_floor_px,
      [this](std::string_view text, double px) { return metrics->width(text, px); });
  std::vector<std::vector<core::Vec2>> pixels;
  for (std::size_t p = 0; p < frame.panels.size() && p < layout.panels.size(); ++p) {
    const frame::PanelModel& panel = frame.panels[p];
    const frame::WorldToPixel to_px = frame::panelMapping(panel, layout.panels[p], layout);
    pixels.emplace_back();
    for (const frame::BodyModel& body : panel.bodies)
      pixels.back().push_back(to_px.toPixel(body.center_m));
  }
  return pixels;
}

std::vector<std::vector<ArrowFormChoice>> FrameSource::State::unplannedForms(double t_s) {
  frame::FrameModel frame = composed(t_s, false);
  if (patterns) patterns->apply(frame, t_s);
  const std::lock_guard<std::mutex> lock(metrics_mutex);
  return arrowForms(
      frame, frame::layoutFrame(
                 frame, size.width_px, size.height_px, size.text_floor_px,
                 [this](std::string_view text, double px) { return metrics->width(text, px); }));
}

void FrameSource::State::planArrowForms(const std::vector<double>& event_times_s,
                                        double duration_s) {
  // Only where a 2D panel draws velocity arrows (a gas draws none).
  if (std::none_of(panels.begin(), panels.end(), [](const Panel& panel) {
        return panel.scene.dimensions == 2 && panel.plan.arrow_m_per_mps > 0.0 &&
               !isGas(panel.scene);
      })) {
    return;
  }
  arrow_forms = std::make_unique<ArrowFormPlan>(event_times_s, duration_s,
                                                [this](double t_s) { return unplannedForms(t_s); });
}

FrameSource::FrameSource(scene::SceneDesc scene, std::vector<SimulatedPanel> panels,
                         PictureSize size, std::unique_ptr<text::TextMeasure> text_measure)
    : state_(std::make_unique<State>()) {
  COLLIDE_ASSERT(!panels.empty(), "FrameSource: a picture needs at least one simulated panel");
  COLLIDE_ASSERT(size.width_px > 0 && size.height_px > 0, "FrameSource: picture size must be > 0");
  State& s = *state_;
  s.size = size;
  COLLIDE_ASSERT(text_measure != nullptr, "FrameSource: placing labels needs a text measure");
  s.metrics = std::move(text_measure);
  s.theme = &themeNamed(scene.view.theme, "view.theme");
  const scene::ViewDesc& view = scene.view;
  for (SimulatedPanel& panel : panels) s.panels.push_back(makePanel(std::move(panel)));
  if (s.panels.size() > 1) shareOneCamera(s.panels);
  std::vector<double> collision_times;
  for (const Panel& panel : s.panels) {
    for (const physics::CollisionEvent& event : panel.timeline.collisions()) {
      collision_times.push_back(event.time_s);
    }
  }
  // One format per quantity for the whole picture, whichever panel holds its largest value.
  std::vector<const FramePlan*> plans;
  for (const Panel& panel : s.panels) plans.push_back(&panel.plan);
  const PictureFormats formats = formatsFor(plans, scene.duration_s);
  for (Panel& panel : s.panels) panel.plan.formats = formats;
  // A printed figure is one frame, never a video: its legend holds only what that frame shows
  // (a "lost" entry of the run's last instant would take a row from its scene at 8 cm).
  if (!(size.text_floor_px > 0.0))
    planBarLegends(s.panels, *s.theme, *s.metrics, shotStarts(collision_times));
  LabelTimeline::Picture picture;
  picture.compose = [&s](double t_s) { return s.planned(t_s); };
  picture.place = [&s](frame::FrameModel& frame, const LabelSlots* keep, LabelSlots* chosen) {
    s.place(frame, keep, chosen);
  };
  picture.body_px = [&s](const frame::FrameModel& frame) { return s.bodyPixels(frame); };
  picture.probe = [&s](const frame::FrameModel& frame) { return s.probe(frame); };
  picture.playback_at = [&s](double t_s) { return s.time_map.playbackAt(t_s); };
  // Before the labels are planned: the working's column narrows the panels they are placed in.
  if (view.working) s.working = workingPanel(s.panels.front().timeline);
  s.subtitle_room = subtitleRoom(view, collision_times);
  // The info and caption wrapped once for the whole video, their boxes as the widest text needs
  // (a shot whose text took a line more would move everything under it at its first frame),
  // their lines held still through each shot.
  s.patterns = std::make_unique<TextPatterns>(
      shotStarts(collision_times), scene.duration_s,
      [&s](double t_s) { return s.composed(t_s, false); },
      [&s](std::string_view text, double px) {
        const std::lock_guard<std::mutex> lock(s.metrics_mutex);
        return s.metrics->width(text, px);
      },
      frame::computeFrameLayout(size.width_px, size.height_px).text_px);
  s.planArrowForms(collision_times, scene.duration_s);
  s.time_map = TimeMap(scene.duration_s, collision_times, view.slow_motion_factor);
  s.labels = std::make_unique<LabelTimeline>(std::move(collision_times), scene.duration_s,
                                             std::move(picture));
  if (view.chart && view.chart_quantity != kSpeedChartQuantity) {  // the histogram: per frame
    const Panel& first = s.panels.front();
    s.chart = buildChart(first.scene, first.timeline, first.plan, *s.theme, view.chart_quantity);
  }
  s.scene = std::move(scene);
}

FrameSource::FrameSource(FrameSource&&) noexcept = default;
FrameSource& FrameSource::operator=(FrameSource&&) noexcept = default;
FrameSource::~FrameSource() = default;

double FrameSource::duration_s() const {
  return state_->time_map.playbackDuration_s();
}
double FrameSource::simulatedDuration_s() const {
  return state_->scene.duration_s;
}
const scene::SceneDesc& FrameSource::scene() const {
  return state_->scene;
}
const physics::Timeline& FrameSource::timeline() const {
  return state_->panels.front().timeline;
}
std::size_t FrameSource::panelCount() const {
  return state_->panels.size();
}
const physics::Timeline& FrameSource::panelTimeline(std::size_t index) const {
  return state_->panels.at(index).timeline;
}
const std::string& FrameSource::panelHeading(std::size_t index) const {
  return state_->panels.at(index).heading;
}
std::vector<double> frameSimulatedTimes(const scene::SceneDesc& scene,
                                        const physics::Timeline& timeline, int fps,
                                        const std::function<int(double)>& frame_count) {
  std::vector<double> collision_times;
  for (const physics::CollisionEvent& event : timeline.collisions()) {
    collision_times.push_back(event.time_s);
  }
  const TimeMap time_map(scene.duration_s, std::move(collision_times),
                         scene.view.slow_motion_factor);
  const int frames = frame_count(time_map.playbackDuration_s());
  std::vector<double> times;
  times.reserve(static_cast<std::size_t>(std::max(frames, 0)));
  for (int k = 0; k < frames; ++k) {
    const double playback_s = static_cast<double>(k) / fps;
    times.push_back(std::clamp(time_map.simulatedAt(playback_s), 0.0, scene.duration_s));
  }
  return times;
}

double FrameSource::simulatedAt(double playback_s) const {
  return state_->time_map.simulatedAt(playback_s);
}

frame::FrameModel FrameSource::frameAt(double playback_s) const {
  const double t_s = std::clamp(simulatedAt(playback_s), 0.0, state_->scene.duration_s);
  frame::FrameModel frame = state_->frameAt(t_s, false);
  // Playback speed is a fact of the video only: a still (frameAtSimulated) never says it.
  const double slowdown = state_->time_map.slowdownAt(t_s);
  if (slowdown > 1.05) {
    frame.subtitle = slowMotionSubtitle(text::formatPlain(slowdown, text::defaultStyle(), 2));
    frame.subtitle_room = state_->subtitle_room;
  }
  return frame;
}

frame::FrameModel FrameSource::State::frameAt(double t_s, bool whole_run) {
  t_s = std::clamp(t_s, 0.0, scene.duration_s);
  frame::FrameModel frame = whole_run ? composed(t_s, true) : planned(t_s);
  if (whole_run) {
    place(frame);
  } else {
    labels->place(frame, t_s);
  }
  return frame;
}

frame::FrameModel FrameSource::State::stillAt(double t_s) {
  t_s = std::clamp(t_s, 0.0, scene.duration_s);
  frame::FrameModel frame = planned(t_s);
  labels->placeWhole(frame, t_s);
  // A fade is motion: a still shows each label whole where the video's frame at t_s places it.
  showWhole(frame);
  return frame;
}

frame::FrameModel FrameSource::State::composed(double t_s, bool whole_run) const {
  const State& s = *this;
  t_s = std::clamp(t_s, 0.0, s.scene.duration_s);
  frame::FrameModel frame = s.emptyFrame();
  const PictureFormats& formats = s.panels.front().plan.formats;
  frame.time_readout = timeText(t_s, formats);
  const bool grid = s.panels.size() > 1;
  for (const Panel& panel : s.panels) {
    frame::PanelModel model =
        buildPanel(panel.scene, panel.timeline, panel.plan, *s.theme, t_s, whole_run);
    model.heading = panel.heading;
    if (grid && !frame.panels.empty()) {
      // One scale for the whole grid, stated once, in the first panel.
      model.scale_arrow_mps = 0.0;
      model.scale_arrow_label.clear();
    }
    if (grid) {
      // Small cells: no ruler, and a shorter info line (the start momentum is the caption's).
      model.ruler = false;
      const physics::Snapshot now = panel.timeline.sample(t_s);
      core::Vec2 p{0.0, 0.0};
      for (std::size_t i = 0; i < now.bodies.size(); ++i) {
        p += panel.timeline.world().bodies[i].mass_kg *
             (now.bodies[i].velocity_mps - panel.plan.frame_velocity_mps);
      }
      model.info = collisionsSoFar(now.impactCount()) + "   " +
                   text::equation(std::string("Σ") + text::symbol(text::Symbol::kMomentum),
                                  momentumText(p, panel.scene.dimensions, formats));
    }
    frame.panels.push_back(std::move(model));
  }
  frame.panel_columns = frame.panels.size() > 3 ? 2 : 1;
  if (s.chart) {
    frame.charts.push_back(*s.chart);
    frame.charts.back().cursor_x = t_s;
  }
  frame.working = s.working;
  if (frame.working && !s.panels.front().timeline.collisions().empty()) {
    frame.working->shown_lines =
        workingLinesShown(*frame.working, s.panels.front().timeline.collisions().front().time_s,
                          s.scene.duration_s, t_s);
  }
  if (s.scene.view.chart && s.scene.view.chart_quantity == kSpeedChartQuantity) {
    const Panel& first = s.panels.front();
    frame.charts.push_back(speedHistogram(first.timeline, first.plan, *s.theme, t_s));
  }
  return frame;
}

frame::FrameModel FrameSource::frameAtSimulated(double t_s) const {
  return state_->stillAt(t_s);
}

frame::FrameModel FrameSource::chartFrame() const {
  const State& s = *state_;
  const Panel& first = s.panels.front();
  frame::FrameModel frame = s.emptyFrame();
  frame.charts.push_back(s.chart ? *s.chart
                                 : buildChart(first.scene, first.timeline, first.plan, *s.theme,
                                              s.scene.view.chart_quantity));
  return frame;
}

}  // namespace collide::compose
