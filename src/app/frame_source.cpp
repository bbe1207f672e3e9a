#include "app/frame_source.hpp"

#include "app/frame_builder.hpp"
#include "app/world_from_scene.hpp"
#include "physics/simulate.hpp"

namespace collide::app {

struct FrameSource::State {
  scene::SceneDesc scene;
  physics::Timeline timeline;
  FramePlan plan;
};

FrameSource::FrameSource(scene::SceneDesc scene) {
  physics::Timeline timeline = physics::simulate(worldFromScene(scene));
  FramePlan plan = planFrames(scene, timeline);
  state_ = std::make_unique<State>(State{std::move(scene), std::move(timeline), plan});
}

FrameSource::~FrameSource() = default;

double FrameSource::duration_s() const {
  return state_->scene.duration_s;
}
const scene::SceneDesc& FrameSource::scene() const {
  return state_->scene;
}
const physics::Timeline& FrameSource::timeline() const {
  return state_->timeline;
}

render::FrameModel FrameSource::frameAt(double t_s) const {
  return buildFrame(state_->scene, state_->timeline, state_->plan, state_->timeline.sample(t_s));
}

}  // namespace collide::app
