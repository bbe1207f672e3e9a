#pragma once
// A scene's animation as a function of time: simulates once (once per comparison panel), plans
// the camera once, then gives the FrameModel for any time. Pipelines (video, still, strobe, chart,
// batch) sample it; they never look inside.
//
// Two clocks: playback time (what a video's frame k at k/fps shows) and simulated time. They are
// the same unless the scene asks for slow motion around collisions (ViewDesc::slow_motion_factor);
// readouts always show simulated time.
#include <memory>
#include <string>
#include <vector>

#include "physics/timeline.hpp"
#include "render/frame_model.hpp"
#include "scene/scene_desc.hpp"

namespace collide::app {

class FrameSource {
 public:
  // Throws core::InputError for a bad theme or panel parameter in scene.view.
  explicit FrameSource(scene::SceneDesc scene);
  ~FrameSource();

  double duration_s() const;  // playback seconds (longer than the scene's with slow motion)
  double simulatedDuration_s() const;
  const scene::SceneDesc& scene() const;
  const physics::Timeline& timeline() const;  // the first panel's
  // Every panel's physics warnings (physicsWarnings), for the user.
  std::vector<std::string> warnings() const;
  // Simulated time shown at playback time p.
  double simulatedAt(double playback_s) const;

  // The picture at playback time p (clamped to [0, duration_s()]).
  render::FrameModel frameAt(double playback_s) const;
  // The picture at simulated time t (clamped to [0, simulatedDuration_s()]).
  render::FrameModel frameAtSimulated(double t_s) const;
  // A stroboscope photograph: the bodies at t = k / rate_hz over the whole scene, earlier images
  // fainter, the last one solid and labelled.
  render::FrameModel strobeFrame(double rate_hz) const;
  // The scene's chart alone (ViewDesc::chart_quantity), over the whole time.
  render::FrameModel chartFrame() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace collide::app
