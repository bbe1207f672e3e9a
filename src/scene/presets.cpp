#include <functional>

#include "scene/scene_desc.hpp"
#include "scene/suggest.hpp"

namespace collide::scene {
namespace {

// The reference article's worked example: equal 1 kg carts closing at 2 m/s and -1 m/s, e = 0.5.
// They meet at t = 3.5 m / 3 m/s = 7/6 s; 4 s leaves time to watch them separate.
SceneDesc workedExample() {
  SceneDesc scene;
  scene.name = "worked-example";
  scene.title = "Inelastic collision, e = 0.5";
  scene.dimensions = 1;
  scene.duration_s = 4.0;
  scene.restitution = 0.5;
  scene.bodies.push_back({"cart 1", "block", 1.0, 0.5, {-2.0, 0.0}, {2.0, 0.0}, std::nullopt});
  scene.bodies.push_back({"cart 2", "block", 1.0, 0.5, {2.0, 0.0}, {-1.0, 0.0}, std::nullopt});
  return scene;
}

struct PresetEntry {
  PresetInfo info;
  std::function<SceneDesc()> make;
};

const std::vector<PresetEntry>& presetTable() {
  static const std::vector<PresetEntry> table = {
      {{"worked-example", "1 kg at +2 m/s meets 1 kg at -1 m/s, e = 0.5 (the default)"},
       workedExample},
  };
  return table;
}

}  // namespace

const std::vector<PresetInfo>& presetList() {
  static const std::vector<PresetInfo> list = [] {
    std::vector<PresetInfo> infos;
    for (const PresetEntry& entry : presetTable()) infos.push_back(entry.info);
    return infos;
  }();
  return list;
}

SceneDesc loadPreset(const std::string& name) {
  std::vector<std::string> names;
  for (const PresetEntry& entry : presetTable()) {
    if (entry.info.name == name) return entry.make();
    names.push_back(entry.info.name);
  }
  throw SceneError("scene: '" + name + "': no such preset or file" + didYouMean(name, names) +
                   " (run 'collide presets' for the list)");
}

}  // namespace collide::scene
