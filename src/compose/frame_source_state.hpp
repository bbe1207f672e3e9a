// SPDX-License-Identifier: MIT
#pragma once
// Private to FrameSource (frame_source.cpp, frame_source_strobe.cpp): its panels and its state,
// which both files' members read.
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "compose/arrow_forms.hpp"
#include "compose/frame_builder.hpp"
#include "compose/frame_source.hpp"
#include "compose/label_placement.hpp"
#include "compose/label_probe.hpp"
#include "compose/label_timeline.hpp"
#include "compose/palette.hpp"
#include "compose/scale_arrow.hpp"
#include "compose/slow_motion.hpp"
#include "compose/text_patterns.hpp"
#include "frame/layout.hpp"
#include "text/language.hpp"

namespace collide::compose {

struct Panel {
  scene::SceneDesc scene;
  physics::Timeline timeline;
  FramePlan plan;
  std::string heading;
};

struct FrameSource::State {
  scene::SceneDesc scene;
  const Theme* theme = nullptr;
  std::vector<Panel> panels;
  TimeMap time_map{1.0, {}, 1.0};
  std::optional<frame::ChartModel> chart;
  std::optional<frame::WorkingModel> working;  // ViewDesc::working: beside the scene
  PictureSize size;
  // Placing labels measures text; frames may be asked for from more than one thread.
  std::unique_ptr<text::TextMeasure> metrics;
  std::mutex metrics_mutex;
  // Where the labels stand over time (label_timeline.hpp).
  std::unique_ptr<LabelTimeline> labels;
  // How the info and caption wrap in each shot (text_patterns.hpp).
  std::unique_ptr<TextPatterns> patterns;
  // Which 2D arrows go beside their bodies first (arrow_forms.hpp); null: no 2D panel.
  std::unique_ptr<ArrowFormPlan> arrow_forms;
  // The widest slow-motion subtitle the video shows (FrameModel::subtitle_room); empty: none.
  std::string subtitle_room;
  // The strobe's own span (compose::strobeSpan_s samples each timeline hundreds of times):
  // found once, as the rate, the image count and the frame all ask for it.
  std::once_flag strobe_span_once;
  double strobe_span_s = 0.0;

  double ownStrobeSpan_s();

  // A frame of this picture with nothing drawn in it yet: the theme, the number style, the
  // language and the title every frame (animation, strobe, chart) starts from.
  frame::FrameModel emptyFrame() const {
    frame::FrameModel frame;
    frame.style = theme->style;
    frame.style.numbers = text::defaultStyle();
    frame.lang = text::activeLanguage().tag;
    frame.style.right_to_left = text::activeLanguage().right_to_left;
    frame.title = scene.title;
    return frame;
  }

  // The picture at simulated time t_s; whole_run: the last state of a strobe.
  frame::FrameModel frameAt(double t_s, bool whole_run);
  // The still at simulated time t_s: the video's frame there with every text whole.
  frame::FrameModel stillAt(double t_s);
  // The same, its labels not placed yet.
  frame::FrameModel composed(double t_s, bool whole_run) const;
  // A frame of the video, its labels not placed yet: composed, its texts wrapped as in its shot,
  // its arrows' forms as planned.
  frame::FrameModel planned(double t_s) {
    frame::FrameModel frame = composed(t_s, false);
    if (patterns) patterns->apply(frame, t_s);
    if (arrow_forms) arrow_forms->apply(frame, t_s);
    return frame;
  }
  // The arrows' forms in the frame at t_s as drawn with none planned (ArrowFormPlan's sample).
  std::vector<std::vector<ArrowFormChoice>> unplannedForms(double t_s);
  // Sets arrow_forms where a 2D panel draws velocity arrows (`event_times_s`: every panel's), so
  // that the labels are planned around the arrows as they will be drawn.
  void planArrowForms(const std::vector<double>& event_times_s, double duration_s);

  // What label places cost in `frame` (its labels not placed yet), as place() would place them.
  LabelProbe probe(frame::FrameModel frame) {
    const std::lock_guard<std::mutex> lock(metrics_mutex);
    fitScaleArrows(
        frame, frame::layoutFrame(
                   frame, size.width_px, size.height_px, size.text_floor_px,
                   [this](std::string_view text, double px) { return metrics->width(text, px); }));
    return LabelProbe(std::move(frame), size.width_px, size.height_px, *metrics,
                      size.text_floor_px);
  }

  // Each body's centre in pixels, per panel, as the painters place it.
  std::vector<std::vector<core::Vec2>> bodyPixels(const frame::FrameModel& frame);

  void place(frame::FrameModel& frame, const LabelSlots* keep = nullptr,
             LabelSlots* chosen = nullptr) {
    const std::lock_guard<std::mutex> lock(metrics_mutex);
    // The scale arrow first: its label's width is part of the layout the labels are placed in.
    fitScaleArrows(
        frame, frame::layoutFrame(
                   frame, size.width_px, size.height_px, size.text_floor_px,
                   [this](std::string_view text, double px) { return metrics->width(text, px); }));
    placeLabels(frame, size.width_px, size.height_px, *metrics, size.text_floor_px, keep, chosen);
  }
};

}  // namespace collide::compose
