// SPDX-License-Identifier: MIT
#pragma once
// The parts of the extension module _collide, each registered by its own file, and what they share.
#include <pybind11/pybind11.h>

#include "scene_recipe.hpp"

namespace collide::python {

namespace py = pybind11;

// A recipe as the Python Scene hands it over: (source, is_text, text_name, overrides, duration,
// duration_typed), each override (key, value, origin, kind) with kind 0 value, 1 speed,
// 2 direction (scene::Override::Kind).
SceneRecipe recipeFrom(const py::tuple& recipe);

void bindErrors(py::module_& module);    // module.cpp
void bindScene(py::module_& module);     // bind_scene.cpp
void bindRun(py::module_& module);       // bind_run.cpp
void bindPictures(py::module_& module);  // bind_pictures.cpp
void bindSolve(py::module_& module);     // bind_solve.cpp

}  // namespace collide::python
