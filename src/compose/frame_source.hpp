#pragma once
// A scene's animation as a function of time: takes the scene's Timeline (one per comparison
// panel, simulated by the caller), plans the camera once, then gives the FrameModel for any time.
// Pipelines (video, still, strobe, chart, batch) sample it; they never look inside.
//
// Two clocks: playback time (what a video's frame k at k/fps shows) and simulated time. They are
// the same unless the scene asks for slow motion around collisions (ViewDesc::slow_motion_factor);
// readouts always show simulated time.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "frame/frame_model.hpp"
#include "physics/timeline.hpp"
#include "scene/scene_desc.hpp"
#include "text/text_measure.hpp"

namespace collide::compose {

// One picture of a scene: the scene itself, or one comparison panel's variant of it
// (ViewDesc::panel_values) with its heading, e.g. "e = 0.5".
struct PanelScene {
  scene::SceneDesc scene;
  std::string heading;  // empty for a single picture
};

// The scenes to simulate for `scene`'s picture, in panel order: the scene itself, or one per
// value of view.panel_values. Throws core::InputError for a bad panel parameter.
std::vector<PanelScene> panelScenes(const scene::SceneDesc& scene);

// The picture's size: labels are placed for it (label_placement.hpp).
struct PictureSize {
  int width_px = 0;  // both > 0
  int height_px = 0;
  double text_floor_px = 0.0;  // a printed figure's smallest text (frame::printTextFloorPx)
};

// A panel scene with its simulated Timeline.
struct SimulatedPanel {
  PanelScene panel;
  physics::Timeline timeline;
};

// The simulated time each frame of the scene's video shows (frame k at playback time k / fps, for
// frame_count(playback duration) frames): FrameSource's clock, slow motion around `timeline`'s
// collisions included, without composing a picture (a Tracker model's rows follow the frames).
std::vector<double> frameSimulatedTimes(const scene::SceneDesc& scene,
                                        const physics::Timeline& timeline, int fps,
                                        const std::function<int(double)>& frame_count);

class FrameSource {
 public:
  // `panels` are panelScenes(scene), each with its Timeline, in the same order (at least one).
  // Labels are placed with widths from `text_measure`: the painter's (render::TextMetrics), so
  // that what is placed is what is drawn. Throws core::InputError for a bad theme in scene.view.
  FrameSource(scene::SceneDesc scene, std::vector<SimulatedPanel> panels, PictureSize size,
              std::unique_ptr<text::TextMeasure> text_measure);
  FrameSource(FrameSource&&) noexcept;
  FrameSource& operator=(FrameSource&&) noexcept;
  ~FrameSource();

  double duration_s() const;  // playback seconds (longer than the scene's with slow motion)
  double simulatedDuration_s() const;
  const scene::SceneDesc& scene() const;
  const physics::Timeline& timeline() const;  // the first panel's
  std::size_t panelCount() const;
  const physics::Timeline& panelTimeline(std::size_t index) const;
  const std::string& panelHeading(std::size_t index) const;  // "" for a single picture
  // Simulated time shown at playback time p.
  double simulatedAt(double playback_s) const;

  // The picture at playback time p (clamped to [0, duration_s()]).
  frame::FrameModel frameAt(double playback_s) const;
  // The picture at simulated time t (clamped to [0, simulatedDuration_s()]): a still, the
  // video's frame at t with every text whole (a label fading between its body and its legend
  // in the video stands solid where the frame places it; compose/label_fades.hpp).
  frame::FrameModel frameAtSimulated(double t_s) const;
  // A stroboscope photograph: the bodies at t = k / rate_hz over strobeSpan_s(keep_apart), earlier
  // images fainter, the last one solid and labelled. keep_apart: no two images of a body overlap,
  // a body at rest is drawn once (strobe_plan.hpp's strobeGhosts); else every flash shows every
  // body.
  frame::FrameModel strobeFrame(double rate_hz, bool keep_apart) const;
  // rate_hz <= 0: the picture's own rate (strobeRate_hz()), images kept apart; a rate > 0 is the
  // user's, and every flash is drawn.
  frame::FrameModel strobeFrame(double rate_hz) const {
    return strobeFrame(rate_hz, !(rate_hz > 0.0));
  }
  // The rate a teacher would set the stroboscope to: the fastest round rate (50, 40, 25, 20, 10,
  // 8, 5, 4, 2.5, 2, 1, 0.5, 0.25 or 0.1 per second) at which no body's image overlaps its next
  // one (images of a body at rest stack into one), with at least kMinStrobeImages images
  // (strobe_plan.hpp); else the slowest rate that still gives that many.
  double strobeRate_hz() const;
  // The end of the time a strobe photographs, from 0: keep_apart (the picture's own rate), up to
  // where every body turns at once after a collision (strobe_plan.hpp's strobeSpan_s), else the
  // whole scene (a rate the user gives draws every flash of the run).
  double strobeSpan_s(bool keep_apart = true) const;
  // The flashes of a strobe at rate_hz over strobeSpan_s(keep_apart) (at most 2000).
  int strobeImages(double rate_hz, bool keep_apart) const;
  // The scene's chart alone (ViewDesc::chart_quantity), over the whole time.
  frame::FrameModel chartFrame() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace collide::compose
