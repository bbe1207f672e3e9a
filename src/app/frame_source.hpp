#pragma once
// A scene's animation as a function of time: simulates once, plans the camera once, then gives the
// FrameModel for any simulated time. Pipelines (video, still, strobe, batch) sample it; they never
// look inside.
#include <memory>

#include "physics/timeline.hpp"
#include "render/frame_model.hpp"
#include "scene/scene_desc.hpp"

namespace collide::app {

class FrameSource {
 public:
  explicit FrameSource(scene::SceneDesc scene);
  ~FrameSource();

  double duration_s() const;
  const scene::SceneDesc& scene() const;
  const physics::Timeline& timeline() const;
  // The picture at simulated time t (clamped to [0, duration]).
  render::FrameModel frameAt(double t_s) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace collide::app
