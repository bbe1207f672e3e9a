#include "app/scene_options.hpp"

namespace collide::app {

void SceneOptions::addTo(CLI::App& command) {
  command.add_option("SCENE", scene, "Preset name (see 'collide presets')")->required();
  duration_option = command.add_option("--duration", duration_s,
                                       "Simulated seconds (default: the scene's duration)");
}

scene::SceneDesc SceneOptions::load() const {
  scene::SceneDesc loaded = scene::loadPreset(scene);
  if (duration_option->count() > 0) {
    checkDuration(duration_s, "--duration");
    loaded.duration_s = duration_s;
  }
  return loaded;
}

void SizeOption::addTo(CLI::App& command) {
  command.add_option("--size", text, "Frame size WIDTHxHEIGHT, 16x16 to 7680x4320")
      ->capture_default_str();
}

}  // namespace collide::app
