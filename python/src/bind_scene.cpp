// SPDX-License-Identifier: MIT
// Scenes: the presets, a scene checked, and a scene written as a scene file.
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "scene/scene_io.hpp"

namespace collide::python {
namespace {

py::list presetList() {
  py::list presets;
  for (const scene::PresetInfo& preset : scene::presetList()) {
    presets.append(py::make_tuple(preset.name, preset.summary));
  }
  return presets;
}

// Reads the scene (raising SceneError as the program would exit 2) and says what it is.
py::dict describe(const py::tuple& recipe_tuple) {
  const SceneRecipe recipe = recipeFrom(recipe_tuple);
  scene::SceneDesc loaded;
  runReleased([&] {
    std::unique_ptr<LanguageHold> hold;
    loaded = loadForData(recipe, hold);
  });
  py::dict info;
  info["name"] = loaded.name;
  info["title"] = loaded.title;
  info["duration"] = loaded.duration_s;
  info["dimensions"] = loaded.dimensions;
  info["bodies"] = loaded.bodies.size();
  info["lang"] = loaded.lang;
  return info;
}

std::string toToml(const py::tuple& recipe_tuple, const std::string& lang) {
  const SceneRecipe recipe = recipeFrom(recipe_tuple);
  std::string text;
  runReleased([&] {
    std::unique_ptr<LanguageHold> hold;
    text = scene::sceneToToml(loadForPicture(recipe, lang, hold));
  });
  return text;
}

}  // namespace

void bindScene(py::module_& module) {
  module.def("presets", &presetList, "Every preset as (name, one-line description), in order");
  module.def("describe", &describe, py::arg("recipe"),
             "Reads a scene recipe and returns its name, title, duration, dimensions, body "
             "count and language; raises SceneError for bad input");
  module.def("to_toml", &toToml, py::arg("recipe"), py::arg("lang") = "",
             "The scene as a scene file that reads back to the same scene");
}

}  // namespace collide::python
