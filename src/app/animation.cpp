#include "app/animation.hpp"

#include "app/simulation_progress.hpp"
#include "app/world_from_scene.hpp"
#include "render/text/text_metrics.hpp"
#include "report/physics_warnings.hpp"

namespace collide::app {

Animation animate(const scene::SceneDesc& scene, compose::PictureSize size) {
  std::vector<compose::SimulatedPanel> panels;
  std::vector<std::string> warnings;
  for (compose::PanelScene& panel : compose::panelScenes(scene)) {
    physics::Timeline timeline = simulateReporting(worldFromScene(panel.scene));
    for (std::string& line : report::physicsWarnings(timeline, panel.heading)) {
      warnings.push_back(std::move(line));
    }
    panels.push_back({std::move(panel), std::move(timeline)});
  }
  return {
      compose::FrameSource(scene, std::move(panels), size, std::make_unique<render::TextMetrics>()),
      std::move(warnings)};
}

}  // namespace collide::app
