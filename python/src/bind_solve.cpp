// SPDX-License-Identifier: MIT
// The working of an impact (collide solve): the laws, the scene's numbers substituted and the
// result, written as text, LaTeX, Markdown and MathML.
#include <pybind11/stl.h>

#include "app/simulation_progress.hpp"
#include "app/world_from_scene.hpp"
#include "bindings.hpp"
#include "core/error.hpp"
#include "core/typed_text.hpp"
#include "working/working.hpp"
#include "working/writers.hpp"

namespace collide::python {
namespace {

// Impact `impact` (1-based) of the scene's run, as `collide solve --impact` checks it.
std::size_t checkedImpact(long impact, std::size_t count, const std::string& scene) {
  if (count == 0) {
    throw core::InputError("solve: '" + core::echoTyped(scene) +
                           "': no impact in its simulated time; allowed: a scene whose bodies "
                           "collide (a longer duration?)");
  }
  if (impact < 1 || static_cast<std::size_t>(impact) > count) {
    const std::string allowed = count == 1 ? "1" : "1 to " + std::to_string(count);
    throw core::InputError("impact: '" + std::to_string(impact) + "': no such impact in '" +
                           core::echoTyped(scene) + "'; allowed: " + allowed);
  }
  return static_cast<std::size_t>(impact - 1);
}

// The working in each format, its words in `lang` (else the scene's language, else English).
py::dict solve(const py::tuple& recipe_tuple, long impact, const std::string& lang) {
  const SceneRecipe recipe = recipeFrom(recipe_tuple);
  working::Working written;
  std::string text, latex, markdown, mathml;
  runReleased([&] {
    std::unique_ptr<LanguageHold> hold;
    const scene::SceneDesc scene = loadForPicture(recipe, lang, hold);
    const physics::Timeline timeline = app::simulateReporting(app::worldFromScene(scene));
    const std::size_t index = checkedImpact(impact, working::impactCount(timeline), scene.name);
    written = working::workingFor(timeline, index);
    text = working::writeText(written);
    latex = working::writeLatex(written);
    markdown = working::writeMarkdown(written);
    mathml = working::writeMathml(written);
  });
  py::dict result;
  result["title"] = written.title;
  result["text"] = text;
  result["latex"] = latex;
  result["markdown"] = markdown;
  result["mathml"] = mathml;
  return result;
}

}  // namespace

void bindSolve(py::module_& module) {
  module.def("solve", &solve, py::arg("recipe"), py::arg("impact"), py::arg("lang"),
             "The working of one impact, as collide solve writes it in each format");
}

}  // namespace collide::python
